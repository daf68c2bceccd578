#include "core/image/VideoEncoder.h"

#include "core/support/AtomicFile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdlib>

namespace facet {

bool isVideoPath(const std::string& path)
{
    const QString suffix = QFileInfo(QString::fromStdString(path)).suffix().toLower();
    return suffix == QStringLiteral("mp4") || suffix == QStringLiteral("webm");
}

std::string findFfmpeg()
{
    if (const char* configured = std::getenv("FACET_FFMPEG"); configured && *configured) {
        const QFileInfo file(QString::fromLocal8Bit(configured));
        return file.isFile() && file.isExecutable() ? file.absoluteFilePath().toStdString() : std::string();
    }
    return QStandardPaths::findExecutable(QStringLiteral("ffmpeg")).toStdString();
}

std::string missingFfmpegAdvice(const std::string& videoPath, const std::string& framesHint)
{
    return "writing " + videoPath
        + " needs ffmpeg, which is not installed (Debian: sudo apt install ffmpeg); or write the frames: "
        + framesHint;
}

bool encodeVideo(const std::string& framePattern, int fps, const std::string& videoPath, std::string* error)
{
    const std::string ffmpeg = findFfmpeg();
    if (ffmpeg.empty()) {
        *error = missingFfmpegAdvice(videoPath, "-o frames_####.png");
        return false;
    }
    const QFileInfo destination(QString::fromStdString(videoPath));
    const QString suffix = destination.suffix().toLower();
    // ffmpeg writes into a folder of its own; the bytes then go to the destination as every file
    // Facet writes does (core/support/AtomicFile.h: a temporary beside it, renamed over it).
    QTemporaryDir folder;
    if (!folder.isValid()) {
        *error = videoPath + ": no temporary folder for the encoder: " + folder.errorString().toStdString();
        return false;
    }
    const QString partial = folder.filePath(QStringLiteral("video.") + suffix);
    QStringList arguments {QStringLiteral("-y"), QStringLiteral("-loglevel"), QStringLiteral("error"),
        QStringLiteral("-framerate"), QString::number(fps), QStringLiteral("-start_number"),
        QStringLiteral("0"), QStringLiteral("-i"), QString::fromStdString(framePattern),
        QStringLiteral("-vf"), QStringLiteral("pad=ceil(iw/2)*2:ceil(ih/2)*2")};
    if (suffix == QStringLiteral("webm"))
        arguments << QStringLiteral("-c:v") << QStringLiteral("libvpx-vp9") << QStringLiteral("-b:v")
                  << QStringLiteral("0") << QStringLiteral("-crf") << QStringLiteral("30");
    else
        arguments << QStringLiteral("-c:v") << QStringLiteral("libx264") << QStringLiteral("-crf")
                  << QStringLiteral("18") << QStringLiteral("-movflags") << QStringLiteral("+faststart");
    arguments << QStringLiteral("-pix_fmt") << QStringLiteral("yuv420p") << QStringLiteral("-f")
              << (suffix == QStringLiteral("webm") ? QStringLiteral("webm") : QStringLiteral("mp4"))
              << partial;
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(QString::fromStdString(ffmpeg), arguments);
    const bool finished = process.waitForStarted(10000) && process.waitForFinished(-1);
    const QString output = QString::fromLocal8Bit(process.readAll()).trimmed();
    if (!finished || process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0) {
        const QStringList lines = output.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        *error = videoPath + ": ffmpeg failed: "
            + (lines.isEmpty()
                    ? process.errorString()
                    : lines.mid(std::max<qsizetype>(0, lines.size() - 3)).join(QStringLiteral("; ")))
                  .toStdString();
        return false;
    }
    QFile encoded(partial);
    if (!encoded.open(QIODevice::ReadOnly)) {
        *error = videoPath + ": ffmpeg wrote no video";
        return false;
    }
    const QByteArray bytes = encoded.readAll();
    std::string reason;
    if (!writeFileAtomically(
            videoPath, std::string_view(bytes.constData(), std::size_t(bytes.size())), &reason)) {
        *error = videoPath + ": cannot write: " + reason;
        return false;
    }
    return true;
}

} // namespace facet
