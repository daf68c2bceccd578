#include "FullVolume.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

#include <fcntl.h>
#include <sched.h>
#include <spawn.h>
#include <sys/mount.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

namespace facet::test {

namespace {

const QString kFiller = QStringLiteral(".facet-test-filler");

QString& isolationProblemText()
{
    static QString text
        = QStringLiteral("FullVolume::isolateMounts() was not called from the test's initMain()");
    return text;
}

bool& isolated()
{
    static bool value = false;
    return value;
}

QString errnoText(const char* what)
{
    return QStringLiteral("%1: %2").arg(QLatin1String(what), QString::fromLocal8Bit(std::strerror(errno)));
}

// Runs `argv` (a full path first) and waits; its exit status, or -1 when it could not run.
int runQuietly(const std::vector<const char*>& argv)
{
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    std::vector<char*> arguments;
    for (const char* argument : argv)
        arguments.push_back(const_cast<char*>(argument));
    arguments.push_back(nullptr);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, arguments.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        return -1;
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) { }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Not root: a mount namespace needs a user namespace, and unshare(CLONE_NEWUSER) refuses a
// process with threads (OpenImageIO starts its thread pool when it is loaded, before main). So
// the test executable runs itself again, same arguments and same process id, under util-linux's
// `unshare -rm` (a user namespace mapping this user to root, and a mount namespace), once.
// Returns only when that is impossible (problem set).
bool reexecInUserNamespace()
{
    static const char* const kMarker = "FACET_TEST_IN_USER_NAMESPACE";
    if (qEnvironmentVariableIsSet(kMarker)) {
        isolationProblemText() = QStringLiteral("still not root after `unshare -rm`");
        return false;
    }
    const char* unshareTool = nullptr;
    for (const char* candidate : {"/usr/bin/unshare", "/bin/unshare"})
        if (::access(candidate, X_OK) == 0)
            unshareTool = candidate;
    if (!unshareTool) {
        isolationProblemText() = QStringLiteral("not root, and util-linux's unshare is not installed");
        return false;
    }
    if (runQuietly({unshareTool, "-rm", "/bin/true"}) != 0) {
        isolationProblemText()
            = QStringLiteral("not root, and `unshare -rm` is refused here (user namespaces off?)");
        return false;
    }
    QFile commandLine(QStringLiteral("/proc/self/cmdline"));
    if (!commandLine.open(QIODevice::ReadOnly)) {
        isolationProblemText() = QStringLiteral("cannot read /proc/self/cmdline");
        return false;
    }
    const QList<QByteArray> arguments = commandLine.readAll().split('\0');
    QByteArray self(4096, '\0');
    const ssize_t length = ::readlink("/proc/self/exe", self.data(), std::size_t(self.size() - 1));
    if (length <= 0) {
        isolationProblemText() = errnoText("readlink /proc/self/exe");
        return false;
    }
    self.truncate(length);
    std::vector<char*> argv {
        const_cast<char*>(unshareTool), const_cast<char*>("-rm"), const_cast<char*>("--"), self.data()};
    for (qsizetype i = 1; i < arguments.size(); ++i)
        if (!(i == arguments.size() - 1 && arguments[i].isEmpty())) // the trailing NUL
            argv.push_back(const_cast<char*>(arguments[i].constData()));
    argv.push_back(nullptr);
    qputenv(kMarker, "1");
    ::execv(unshareTool, argv.data());
    isolationProblemText() = errnoText("exec unshare -rm");
    return false;
}

} // namespace

bool FullVolume::isolateMounts()
{
    if (isolated())
        return true;
    if (::geteuid() != 0 && !reexecInUserNamespace())
        return false; // (on success reexecInUserNamespace does not return)
    // As root, or as the mapped root of the user namespace after the re-run: a mount namespace.
    // unshare(CLONE_NEWNS) is allowed with threads running (only CLONE_NEWUSER is not).
    if (::unshare(CLONE_NEWNS) != 0) {
        isolationProblemText() = errnoText("unshare(CLONE_NEWNS)");
        return false;
    }
    // Private, recursively: a mount made here must not propagate back to the host's namespace
    // (on systemd hosts "/" is a shared mount).
    if (::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) {
        isolationProblemText() = errnoText("making / a private mount");
        return false;
    }
    isolated() = true;
    isolationProblemText().clear();
    return true;
}

const QString& FullVolume::isolationProblem()
{
    return isolationProblemText();
}

FullVolume::FullVolume(const QString& mountPoint, qint64 bytes)
{
    if (!isolated()) {
        m_problem = isolationProblem();
        return;
    }
    if (mountPoint.isEmpty()) {
        m_temporary = std::make_unique<QTemporaryDir>();
        if (!m_temporary->isValid()) {
            m_problem = QStringLiteral("cannot create a temporary folder to mount on");
            return;
        }
        m_path = m_temporary->path();
    } else {
        m_path = QDir(mountPoint).absolutePath();
        if (!QDir().mkpath(m_path)) {
            m_problem = QStringLiteral("cannot create the mount point %1").arg(m_path);
            return;
        }
    }
    const QByteArray options = "size=" + QByteArray::number(bytes) + ",mode=0755";
    if (::mount("facet-full-volume", QFile::encodeName(m_path).constData(), "tmpfs", MS_NOSUID | MS_NODEV,
            options.constData())
        != 0) {
        m_problem = errnoText("mount -t tmpfs");
        return;
    }
    m_mounted = true;
}

FullVolume::~FullVolume()
{
    // Lazily (MNT_DETACH): a file a failed test left open must not keep the volume mounted.
    if (m_mounted)
        ::umount2(QFile::encodeName(m_path).constData(), MNT_DETACH);
}

QString FullVolume::filePath(const QString& name) const
{
    return QDir(m_path).filePath(name);
}

bool FullVolume::fill()
{
    if (!m_mounted)
        return false;
    const QByteArray path = QFile::encodeName(filePath(kFiller));
    const int fd = ::open(path.constData(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (fd < 0) {
        m_problem = errnoText("creating the filler");
        return false;
    }
    // Large writes first, then smaller ones for what is left of the last page.
    const std::vector<char> block(64 * 1024, 'f');
    for (std::size_t chunk : {block.size(), std::size_t(4096), std::size_t(1)}) {
        for (;;) {
            const ssize_t written = ::write(fd, block.data(), chunk);
            if (written > 0)
                continue;
            if (written < 0 && errno == EINTR)
                continue;
            if (written < 0 && errno != ENOSPC) {
                m_problem = errnoText("filling the volume");
                ::close(fd);
                return false;
            }
            break; // ENOSPC: this chunk size no longer fits
        }
    }
    ::close(fd);
    if (freeBytes() != 0) {
        m_problem = QStringLiteral("the volume still has %1 bytes free after filling").arg(freeBytes());
        return false;
    }
    return true;
}

bool FullVolume::release(qint64 bytes)
{
    const QString filler = filePath(kFiller);
    const qint64 size = QFileInfo(filler).size();
    if (!QFile::resize(filler, std::max<qint64>(0, size - bytes))) {
        m_problem = QStringLiteral("cannot shrink the filler");
        return false;
    }
    return true;
}

bool FullVolume::drain()
{
    return QFile::remove(filePath(kFiller));
}

bool FullVolume::makeReadOnly()
{
    if (!m_mounted)
        return false;
    if (::mount(nullptr, QFile::encodeName(m_path).constData(), nullptr,
            MS_REMOUNT | MS_RDONLY | MS_NOSUID | MS_NODEV, nullptr)
        != 0) {
        m_problem = QStringLiteral("cannot remount %1 read-only: %2")
                        .arg(m_path, QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    return true;
}

qint64 FullVolume::freeBytes() const
{
    struct statvfs info { };
    if (::statvfs(QFile::encodeName(m_path).constData(), &info) != 0)
        return -1;
    return qint64(info.f_bavail) * qint64(info.f_frsize);
}

QStringList FullVolume::entries(const QString& relative) const
{
    QStringList list
        = QDir(relative.isEmpty() ? m_path : filePath(relative))
              .entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot, QDir::Name);
    list.removeAll(kFiller);
    return list;
}

QByteArray fileBytes(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return file.readAll();
}

} // namespace facet::test
