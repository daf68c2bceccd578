#pragma once
// A small, really full file system for the tests of what Facet does when a disk is full
// (tests/SafeWriteTest.cpp, tests/SafeWriteUiTest.cpp): a tmpfs of a few hundred KiB, mounted
// where the test asks, then filled to the last byte.
//
// Mounts never outlive the test process, even when it crashes: a test executable calls
// FullVolume::isolateMounts() from initMain(), before any thread exists, which moves the process
// into a mount namespace of its own (unshare(2), mount_namespaces(7)): as root, CLONE_NEWNS with
// every mount made private. Not root, the executable first runs itself again (same arguments,
// same process id) under util-linux's `unshare -rm`, which adds a user namespace mapping the user
// to root there; unshare(CLONE_NEWUSER) itself refuses a process with threads, and OpenImageIO
// starts its thread pool before main. Child processes (facet render) inherit the namespace and
// see the same full volume; nothing outside the process does. The destructor also unmounts, so
// one test's volume never leaks into the next.

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

#include <memory>

#include "TestSupport.h"

namespace facet::test {

class FullVolume {
public:
    // Call once from initMain(). False (and isolationProblem() says why) when the process may not
    // have a mount namespace of its own, e.g. in a container without CAP_SYS_ADMIN that also
    // forbids user namespaces; every FullVolume is then invalid.
    static bool isolateMounts();
    static const QString& isolationProblem();

    // Mounts a tmpfs of `bytes` at `mountPoint` (created when missing), or at a new temporary
    // folder when `mountPoint` is empty. It starts empty; fill() fills it.
    explicit FullVolume(const QString& mountPoint = {}, qint64 bytes = 256 * 1024);
    ~FullVolume(); // unmounts
    FullVolume(const FullVolume&) = delete;
    FullVolume& operator=(const FullVolume&) = delete;

    bool isValid() const { return m_mounted; }
    const QString& problem() const { return m_problem; }
    const QString& path() const { return m_path; }
    QString filePath(const QString& name) const;

    // Writes a filler file until the file system refuses another byte (ENOSPC), and checks that
    // statvfs then reports no free block. False with problem() set otherwise.
    bool fill();
    // Shrinks the filler by `bytes` (whole pages on tmpfs): room for about that much, no more.
    bool release(qint64 bytes);
    // Removes the filler: the volume has room again.
    bool drain();
    // Remounts the volume read-only: even root cannot write there (an unwritable folder that
    // holds for the root user CI runs as, where a chmod would not).
    bool makeReadOnly();
    qint64 freeBytes() const;

    // Every entry of the folder `relative` (default: the volume's root), hidden ones included,
    // sorted, without the filler: what a failed save must leave unchanged (no temporaries).
    QStringList entries(const QString& relative = {}) const;

private:
    QString m_path;
    std::unique_ptr<QTemporaryDir> m_temporary;
    bool m_mounted = false;
    QString m_problem;
};

// The whole content of a file (empty when it cannot be read), for "the old file is intact".
QByteArray fileBytes(const QString& path);

} // namespace facet::test

// Skips the test (locally) or fails it (under CI=true) when no full volume can be made here.
#define FACET_REQUIRE_FULL_VOLUME(volume)                                                                    \
    do {                                                                                                     \
        if (!(volume).isValid()) {                                                                           \
            const QByteArray message                                                                         \
                = "cannot make a small full tmpfs here: " + (volume).problem().toLocal8Bit();                \
            if (facet::test::runningInCi())                                                                  \
                QFAIL(message.constData());                                                                  \
            else                                                                                             \
                QSKIP(message.constData());                                                                  \
        }                                                                                                    \
    } while (false)
