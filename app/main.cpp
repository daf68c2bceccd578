// facet: the GUI by default; headless commands: render, sheet, bench, bake and export. The command
// line is parsed before any Q*Application exists, so --help, --version and errors need no display
// server; QApplication is made only for the GUI.

#include "BakeCommand.h"
#include "BenchCommand.h"
#include "CommandLine.h"
#include "ExportCommand.h"
#include "RenderCommand.h"
#include "SheetCommand.h"
#include "WindowScreenshot.h"

#include "core/project/Project.h"
#include "ui/MainWindow.h"
#include "ui/document/ProjectFileController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"

#include <QApplication>
#include <QTimer>

#include <cstdio>
#include <optional>

namespace {

constexpr int kExitUsage = 2; // bad command line, unavailable command
constexpr int kExitFailure = 1; // valid request that could not be carried out

// Qt aborts (qFatal) when its platform plugin finds no display; say why before it can.
bool displayServerReachable()
{
    const QString platform = qEnvironmentVariable("QT_QPA_PLATFORM");
    if (!platform.isEmpty() && !platform.startsWith(QStringLiteral("xcb"))
        && !platform.startsWith(QStringLiteral("wayland")))
        return true; // the user chose a platform; let Qt judge it
    return !qEnvironmentVariableIsEmpty("DISPLAY") || !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
}

int runGui(int& argc, char** argv, const facet::CommandLine& commandLine)
{
    if (!displayServerReachable()) {
        std::fprintf(stderr,
            "facet: the main window needs a display server and neither DISPLAY nor WAYLAND_DISPLAY "
            "is set (run it under xvfb-run, or see 'facet --help')\n");
        return kExitFailure;
    }
    facet::installViewportSurfaceFormat();
    QApplication app(argc, argv);

    QString why;
    if (!commandLine.screenshotPath.isEmpty()
        && !facet::WindowScreenshot::canWriteFormatOf(commandLine.screenshotPath, &why)) {
        std::fprintf(stderr, "facet: --screenshot '%s': %s\n", qPrintable(commandLine.screenshotPath),
            qPrintable(why));
        return kExitUsage;
    }

    facet::MainWindow window;
    if (!commandLine.projectPath.isEmpty()) {
        // A project that cannot be opened leaves the default project up and says why (status bar
        // and a message box), and on stderr for whoever started facet from a shell.
        if (!window.projectFiles()->openFile(commandLine.projectPath))
            std::fprintf(stderr, "facet: %s\n", qPrintable(window.projectFiles()->lastError()));
    }
    std::optional<facet::WindowScreenshot> screenshot;
    if (!commandLine.screenshotPath.isEmpty())
        screenshot.emplace(&window, window.viewport(), window.compareView(), commandLine.screenshotPath);
    window.show();
    // Work lost in a crash is offered back, but not to a scripted screenshot run.
    if (!screenshot)
        QTimer::singleShot(0, &window, &facet::MainWindow::offerRecovery);
    return QApplication::exec();
}

// Parses a headless command's arguments and runs it. Both commands share the contract: parse()
// returns nullopt with exit code 0 for --help (the text in `error`), 1 or 2 with a message.
template <typename Command> int runCommand(const char* name, const QStringList& arguments)
{
    QString error;
    int exitCode = 0;
    const auto request = Command::parse(arguments, &error, &exitCode);
    if (!request) {
        if (exitCode == 0) { // --help
            std::fputs(qPrintable(error), stdout);
            return 0;
        }
        std::fprintf(stderr, "facet %s: %s\n", name, qPrintable(error));
        if (exitCode == Command::kExitUsage)
            std::fprintf(stderr, "Try 'facet %s --help' for more information.\n", name);
        return exitCode;
    }
    return Command::run(*request);
}

} // namespace

int main(int argc, char* argv[])
{
    QCoreApplication::setApplicationName(QStringLiteral("facet"));
    QCoreApplication::setApplicationVersion(QStringLiteral(FACET_VERSION));
    QCoreApplication::setOrganizationName(QStringLiteral("Facet"));

    QStringList arguments;
    for (int index = 0; index < argc; ++index)
        arguments.append(QString::fromLocal8Bit(argv[index]));
    const facet::CommandLine commandLine = facet::CommandLine::parse(arguments);
    // Project::defaultProject() reads it and ignores a value it does not know: say so once.
    if (const QByteArray method = qgetenv("FACET_NEW_PROJECT_METHOD");
        !method.isEmpty() && !facet::iblMethodFromString(method.toStdString()))
        std::fprintf(stderr,
            "facet: FACET_NEW_PROJECT_METHOD='%s' is not split-sum, fis or reference: new projects use fis\n",
            method.constData());

    switch (commandLine.action) {
    case facet::CommandLine::Action::ShowHelp:
        std::fputs(qPrintable(facet::CommandLine::helpText()), stdout);
        return 0;
    case facet::CommandLine::Action::ShowVersion:
        std::printf("%s %s\n", qPrintable(QCoreApplication::applicationName()),
            qPrintable(QCoreApplication::applicationVersion()));
        return 0;
    case facet::CommandLine::Action::Command:
        // The commands this version has: CommandLine::availableCommandNames().
        if (commandLine.command == QStringLiteral("bench"))
            return runCommand<facet::BenchCommand>("bench", commandLine.commandArguments);
        if (commandLine.command == QStringLiteral("sheet"))
            return runCommand<facet::SheetCommand>("sheet", commandLine.commandArguments);
        if (commandLine.command == QStringLiteral("bake"))
            return runCommand<facet::BakeCommand>("bake", commandLine.commandArguments);
        if (commandLine.command == QStringLiteral("export"))
            return runCommand<facet::ExportCommand>("export", commandLine.commandArguments);
        return runCommand<facet::RenderCommand>("render", commandLine.commandArguments);
    case facet::CommandLine::Action::Unavailable:
        std::fprintf(
            stderr, "facet: '%s' is not available in this version\n", qPrintable(commandLine.command));
        return kExitUsage;
    case facet::CommandLine::Action::Error:
        std::fprintf(
            stderr, "facet: %s\nTry 'facet --help' for more information.\n", qPrintable(commandLine.error));
        return kExitUsage;
    case facet::CommandLine::Action::Gui:
        break;
    }
    return runGui(argc, argv, commandLine);
}
