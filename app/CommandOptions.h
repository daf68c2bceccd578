#pragma once
// The part of parsing a headless command's arguments that every command shares (render, bench):
// QCommandLineParser wants a program name first; --help answers with exit code 0 and the help
// text in *error; a parse error is a usage error (exit 2).

#include <QCommandLineParser>
#include <QString>
#include <QStringList>

namespace facet {

// The help text of a parser, with Qt's "<executable_name>" placeholder replaced by `program`.
inline QString commandHelpText(const QCommandLineParser& parser, const QString& program)
{
    QString text = parser.helpText();
    text.replace(QStringLiteral("<executable_name>"), program);
    return text;
}

// `Options` has a QCommandLineParser `parser` and a QCommandLineOption `help`. True when the
// command should go on reading options; false with *exitCode (0 for --help, usageExitCode for a
// parse error) and *error (the help text or the parser's message).
template <typename Options>
bool parseCommandOptions(Options& options, const QStringList& arguments, const QString& program,
    int usageExitCode, QString* error, int* exitCode)
{
    *exitCode = usageExitCode;
    QStringList withProgram = arguments;
    withProgram.prepend(program);
    if (!options.parser.parse(withProgram)) {
        *error = options.parser.errorText();
        return false;
    }
    if (options.parser.isSet(options.help)) {
        *exitCode = 0;
        *error = commandHelpText(options.parser, program);
        return false;
    }
    return true;
}

} // namespace facet
