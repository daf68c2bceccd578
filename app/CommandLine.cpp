#include "CommandLine.h"

#include "core/project/AssetProject.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>

namespace facet {

namespace {

struct Parser {
    QCommandLineParser parser;
    QCommandLineOption help {{QStringLiteral("h"), QStringLiteral("help")},
        QStringLiteral("Displays help on command-line options.")};
    QCommandLineOption version {
        {QStringLiteral("v"), QStringLiteral("version")}, QStringLiteral("Displays version information.")};
    QCommandLineOption screenshot {QStringLiteral("screenshot"),
        QStringLiteral("Saves a picture of the main window to <file> (.png) once it has "
                       "drawn its first frame, then quits."),
        QStringLiteral("file")};

    Parser()
    {
        parser.setApplicationDescription(
            QStringLiteral("Facet authors and previews physically based materials.\n"
                           "With no command it opens the main window, on PROJECT.json if given, or on a new\n"
                           "project made from a glTF asset (.gltf, .glb) with its meshes and materials.\n"
                           "Commands (each has --help):\n"
                           "  render   render a project to an EXR or PNG without a display\n"
                           "  sheet    a labelled grid of materials x environments, or a parameter wedge\n"
                           "  bench    time against error of the IBL quality settings (table and CSV)\n"
                           "  bake     an environment's IBL (prefiltered, irradiance, SH9, DFG) as EXR files\n"
                           "  export   materials as engine texture sets (Unreal, Unity, Godot, glTF, templates)"));
        // Our own -h/-v instead of addHelpOption(): its --help-all lists Qt options that this
        // parser, running before QApplication, does not accept.
        parser.addOption(help);
        parser.addOption(version);
        parser.addOption(screenshot);
        parser.addPositionalArgument(QStringLiteral("project"),
            QStringLiteral("Project file (.json) or glTF asset (.gltf, .glb) to open."),
            QStringLiteral("[PROJECT.json|ASSET.glb]"));
    }
};

} // namespace

const QStringList& CommandLine::commandNames()
{
    static const QStringList names = {QStringLiteral("render"), QStringLiteral("sheet"),
        QStringLiteral("bake"), QStringLiteral("export"), QStringLiteral("bench")};
    return names;
}

const QStringList& CommandLine::availableCommandNames()
{
    static const QStringList names
        = {QStringLiteral("render"), QStringLiteral("sheet"), QStringLiteral("bench"), QStringLiteral("bake"),
            QStringLiteral("export")};
    return names;
}

QString CommandLine::helpText()
{
    Parser p;
    QString text = p.parser.helpText();
    // Without a QCoreApplication (none exists yet, on purpose) Qt writes a placeholder for the
    // program; the installed program's name reads better than argv[0] anyway.
    text.replace(QStringLiteral("<executable_name>"), QCoreApplication::applicationName());
    return text;
}

CommandLine CommandLine::parse(const QStringList& arguments)
{
    CommandLine result;
    // A command is the first argument after the program (`facet render --size 512 ...`), so that
    // its own options are its parser's business, not this one's.
    if (arguments.size() > 1 && commandNames().contains(arguments.at(1))) {
        result.command = arguments.at(1);
        if (availableCommandNames().contains(result.command)) {
            result.action = Action::Command;
            result.commandArguments = arguments.mid(2);
        } else {
            result.action = Action::Unavailable;
        }
        return result;
    }

    Parser p;
    if (!p.parser.parse(arguments)) {
        result.action = Action::Error;
        result.error = p.parser.errorText();
        return result;
    }
    if (p.parser.isSet(p.help)) {
        result.action = Action::ShowHelp;
        return result;
    }
    if (p.parser.isSet(p.version)) {
        result.action = Action::ShowVersion;
        return result;
    }

    const QStringList positional = p.parser.positionalArguments();
    // A command after options (`facet --screenshot a.png render`) is still a command, unless "--"
    // said that what follows are file names.
    if (!positional.isEmpty() && commandNames().contains(positional.first())
        && !arguments.contains(QStringLiteral("--"))) {
        // Options before a command belong to the GUI's parser: say so rather than guess.
        result.command = positional.first();
        if (availableCommandNames().contains(result.command)) {
            result.action = Action::Error;
            result.error = QStringLiteral("'%1' must come first: facet %1 [options]").arg(result.command);
        } else {
            result.action = Action::Unavailable;
        }
        return result;
    }
    if (positional.size() > 1) {
        result.action = Action::Error;
        result.error = QStringLiteral("too many arguments: expected at most one project file, got '%1'")
                           .arg(positional.join(QStringLiteral("' '")));
        return result;
    }
    if (!positional.isEmpty()) {
        const QFileInfo project(positional.first());
        if (!project.isFile() || !project.isReadable()) {
            result.action = Action::Error;
            const QString& path = positional.first();
            const QString what
                = isAssetFileName(path.toStdString()) ? QStringLiteral("asset") : QStringLiteral("project");
            if (!project.exists())
                result.error = QStringLiteral("%1 '%2' does not exist").arg(what, path);
            else if (project.isDir())
                result.error = QStringLiteral("%1 '%2' is a directory, not a file").arg(what, path);
            else
                result.error = QStringLiteral("cannot read %1 '%2'").arg(what, path);
            return result;
        }
        result.projectPath = positional.first();
    }
    if (p.parser.isSet(p.screenshot)) {
        result.screenshotPath = p.parser.value(p.screenshot);
        if (result.screenshotPath.isEmpty()) {
            result.action = Action::Error;
            result.error = QStringLiteral("--screenshot needs a file name");
            return result;
        }
    }
    return result;
}

} // namespace facet
