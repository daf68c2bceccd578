#pragma once
// The window's IBL precompute off the GUI thread (not a widget). A thread of its own with a GL
// context of its own that shares with the window's views (one share group: textures made here
// are drawn there) runs IblPrecompute::prepare for the environment a view asks for, disk
// look-up included, while the view keeps drawing the lighting it has (ui/viewport/ViewportRenderer).
// When a set is ready, finished(key) is emitted on the GUI thread; a listener take()s it once
// and puts it into the views' shared IblPrecompute (IblPrecompute::adopt), where every view of
// the window finds it.
//
// One job at a time, two ways to ask. request() is the single view's, newest wins: a request
// for another set cancels the one running (IblProgress, checked after each face of each pass) and
// replaces any queued. enqueue() is the Compare view's: every set of a grid is wanted, so it is
// queued behind the others, in order, and cancels nothing. Either way a set running or queued is
// not asked for twice. Progress is reported as the passes' faces finish on the GPU, at most every
// kProgressIntervalMs.
//
//   auto worker = std::make_shared<LightingWorker>(cacheDirectory, true); // a view's context current
//   connect(worker.get(), &LightingWorker::finished, ...);                  // take(key), adopt
//   worker->request(environment, settings);
//
// Where the platform cannot make a second context current on another thread
// (QOpenGLContext::supportsThreadedOpenGL) or the context cannot be made, isValid() is false and
// the views precompute on the GUI thread as before.
//
// Lifetime: make it with a context of the views' share group current (the GUI thread); destroy
// it on the GUI thread, with or without a context current: the destructor cancels the job, and
// the thread frees its GL objects (its IblPrecompute, results no one took) in its own context
// before it ends.

#include "core/ibl/Environment.h"
#include "render/IblPrecompute.h"
#include "render/IblSettings.h"

#include <QObject>
#include <QString>

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

class QOffscreenSurface;
class QOpenGLContext;
class QThread;

namespace facet {

class LightingWorker : public QObject {
    Q_OBJECT
public:
    static constexpr int kProgressIntervalMs = 50;

    // Needs a context of the views' share group current. `cacheDirectory` empty: the IBL disk
    // cache's default folder; `useDiskCache` false: memory only (tests).
    LightingWorker(const QString& cacheDirectory, bool useDiskCache);
    ~LightingWorker() override;
    LightingWorker(const LightingWorker&) = delete;
    LightingWorker& operator=(const LightingWorker&) = delete;

    // The thread and its context run; otherwise problem() says why not.
    bool isValid() const { return m_thread != nullptr; }
    const QString& problem() const { return m_problem; }

    // Asks for the IBL set of `environment` at `settings` (IblPrecompute::cacheKey, which it
    // returns). Cancels a job for another key and empties the queue.
    std::uint64_t request(const Environment& environment, const IblSettings& settings);
    // Asks for it after the jobs queued (if it is not running or queued already); cancels nothing.
    std::uint64_t enqueue(const Environment& environment, const IblSettings& settings);
    // Cancels the job running or queued, if any (finished() follows with a cancelled result for
    // a running one).
    void cancel();
    // The key of the job queued last, or else of the one running, if any.
    std::optional<std::uint64_t> busyWith() const;

    struct Result {
        std::uint64_t key = 0;
        std::shared_ptr<const IblTextures> textures; // null on failure or cancel
        IblStats stats;
        std::string error; // "IblPrecompute::prepare: ..." on failure
        QString environmentName;
    };
    // The result finished(key) announced, once: the first caller gets it and adopts the set.
    std::optional<Result> take(std::uint64_t key);

Q_SIGNALS:
    // Emitted on the GUI thread (queued from the worker).
    void progress(quint64 key, double fraction);
    void finished(quint64 key);

private:
    struct Job {
        std::uint64_t key = 0;
        Environment environment;
        IblSettings settings;
    };
    void run(); // the thread's body

    QString m_cacheDirectory;
    bool m_useDiskCache = true;
    QString m_problem;
    QOpenGLContext* m_context = nullptr; // lives in the thread once it runs; deleted there
    QOffscreenSurface* m_surface = nullptr; // GUI thread
    QThread* m_thread = nullptr;

    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::deque<Job> m_queue; // oldest first
    std::optional<std::uint64_t> m_running;
    bool m_cancelRunning = false;
    bool m_stop = false;
    // Finished and not taken, oldest first: at most kResultsKept (an older one is dropped by the
    // thread, in its context; the rest at its end). More than a grid's cells: a queue of draft
    // sets (25 ms each) can finish several before the GUI thread, drawing, takes the first.
    static constexpr std::size_t kResultsKept = 12;
    std::vector<Result> m_results;
};

} // namespace facet
