#pragma once
// Facet's command line. It is parsed before any Q*Application exists, so that --help, --version
// and every error work on a machine without a display server.
//
//   facet [--screenshot FILE.png] [PROJECT.json]   the GUI (the default)
//   facet <command> ...                             a headless command (render, bench; sheet,
//                                                   bake and export are not in this version)

#include <QString>
#include <QStringList>

namespace facet {

struct CommandLine {
    enum class Action {
        Gui, // open the main window
        ShowHelp, // print helpText() to stdout, exit 0
        ShowVersion, // print "facet <version>" to stdout, exit 0
        Command, // `command` is a headless command this version has; `commandArguments` follow it
        Unavailable, // `command` names a command this version does not have: exit 2
        Error, // `error` says what is wrong: exit 2
    };

    Action action = Action::Gui;
    QString projectPath; // Gui: the project to open; empty for none
    QString screenshotPath; // Gui: save a grab of the window here after its first frame, then quit
    QString command; // Command, Unavailable: the command asked for
    QStringList commandArguments; // Command: the arguments after the command's name
    QString error; // Error: e.g. "Unknown option 'bogus'."

    // `arguments` as QCoreApplication::arguments() would give them: the program first.
    static CommandLine parse(const QStringList& arguments);
    static QString helpText();
    // The headless commands of the design (docs/architecture.md), whether this version has them or not.
    static const QStringList& commandNames();
    // Those this version has.
    static const QStringList& availableCommandNames();
};

} // namespace facet
