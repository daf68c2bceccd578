// Includes epoxy (render/'s GL loader) before Qt's GL headers would pull in <GL/gl.h>.
#include <epoxy/gl.h>

#include "ui/viewport/LightingWorker.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QThread>

#include <algorithm>
#include <utility>

namespace facet {

LightingWorker::LightingWorker(const QString& cacheDirectory, bool useDiskCache)
    : m_cacheDirectory(cacheDirectory)
    , m_useDiskCache(useDiskCache)
{
    QOpenGLContext* share = QOpenGLContext::currentContext();
    if (!share) {
        m_problem = tr("no GL context is current to share with");
        return;
    }
    if (!QOpenGLContext::supportsThreadedOpenGL()) {
        m_problem = tr("this platform does not support OpenGL on a second thread");
        return;
    }
    m_surface = new QOffscreenSurface;
    m_surface->setFormat(share->format());
    m_surface->create();
    m_context = new QOpenGLContext;
    m_context->setFormat(share->format());
    m_context->setShareContext(share);
    if (!m_surface->isValid() || !m_context->create() || !QOpenGLContext::areSharing(m_context, share)) {
        m_problem = tr("a GL context sharing with the view's could not be made");
        delete m_context;
        m_context = nullptr;
        delete m_surface;
        m_surface = nullptr;
        return;
    }
    m_thread = QThread::create([this] { run(); });
    m_thread->setObjectName(QStringLiteral("facet-lighting"));
    m_context->moveToThread(m_thread);
    m_thread->start();
}

LightingWorker::~LightingWorker()
{
    if (m_thread) {
        {
            const std::lock_guard lock(m_mutex);
            m_stop = true;
            m_cancelRunning = true;
            m_queue.clear();
        }
        m_wake.notify_all();
        m_thread->wait();
        delete m_thread;
    }
    delete m_surface; // the context went with the thread
}

std::uint64_t LightingWorker::request(const Environment& environment, const IblSettings& settings)
{
    const std::uint64_t key = IblPrecompute::cacheKey(environment, settings);
    {
        const std::lock_guard lock(m_mutex);
        m_queue.clear();
        if (m_running == key && !m_cancelRunning)
            return key; // the set wanted is the one running
        if (m_running)
            m_cancelRunning = true;
        m_queue.push_back(Job {key, environment, settings});
    }
    m_wake.notify_all();
    return key;
}

std::uint64_t LightingWorker::enqueue(const Environment& environment, const IblSettings& settings)
{
    const std::uint64_t key = IblPrecompute::cacheKey(environment, settings);
    {
        const std::lock_guard lock(m_mutex);
        if ((m_running == key && !m_cancelRunning)
            || std::any_of(m_queue.begin(), m_queue.end(), [key](const Job& job) { return job.key == key; }))
            return key;
        m_queue.push_back(Job {key, environment, settings});
    }
    m_wake.notify_all();
    return key;
}

void LightingWorker::cancel()
{
    {
        const std::lock_guard lock(m_mutex);
        m_queue.clear();
        if (m_running)
            m_cancelRunning = true;
    }
    m_wake.notify_all();
}

std::optional<std::uint64_t> LightingWorker::busyWith() const
{
    const std::lock_guard lock(m_mutex);
    if (!m_queue.empty())
        return m_queue.back().key;
    if (m_running && !m_cancelRunning)
        return m_running;
    return std::nullopt;
}

std::optional<LightingWorker::Result> LightingWorker::take(std::uint64_t key)
{
    const std::lock_guard lock(m_mutex);
    const auto it
        = std::find_if(m_results.begin(), m_results.end(), [key](const Result& r) { return r.key == key; });
    if (it == m_results.end())
        return std::nullopt;
    Result result = std::move(*it);
    m_results.erase(it);
    return result;
}

void LightingWorker::run()
{
    if (!m_context->makeCurrent(m_surface)) {
        qWarning("LightingWorker: its GL context could not be made current");
        delete m_context;
        return;
    }
    {
        IblPrecompute precompute(m_cacheDirectory, m_useDiskCache);
        for (;;) {
            Job job;
            {
                std::unique_lock lock(m_mutex);
                m_wake.wait(lock, [this] { return m_stop || !m_queue.empty(); });
                if (m_stop)
                    break;
                job = std::move(m_queue.front());
                m_queue.pop_front();
                m_running = job.key;
                m_cancelRunning = false;
            }

            QElapsedTimer sinceReport;
            sinceReport.start();
            const IblProgress progress = [&](double fraction) {
                {
                    const std::lock_guard lock(m_mutex);
                    if (m_cancelRunning)
                        return false;
                }
                if (sinceReport.elapsed() >= kProgressIntervalMs) {
                    sinceReport.restart();
                    Q_EMIT this->progress(job.key, fraction);
                }
                return true;
            };
            Result result;
            result.key = job.key;
            result.environmentName = QString::fromStdString(job.environment.name());
            result.textures
                = precompute.prepare(job.environment, job.settings, &result.stats, &result.error, progress);
            // Every texture complete before another context draws with it.
            glFinish();
            // The views hold the set once one of them adopts it; this precompute keeps nothing.
            precompute.clearMemoryCache();
            if (!result.textures && result.error.empty())
                result.error = "IblPrecompute::prepare: failed";
            std::optional<Result> dropped; // a result nobody took goes here, in this context
            {
                const std::lock_guard lock(m_mutex);
                m_running.reset();
                m_results.erase(std::remove_if(m_results.begin(), m_results.end(),
                                    [&](const Result& r) { return r.key == job.key; }),
                    m_results.end());
                if (m_results.size() >= kResultsKept) {
                    dropped = std::move(m_results.front());
                    m_results.erase(m_results.begin());
                }
                m_results.push_back(std::move(result));
            }
            dropped.reset();
            Q_EMIT finished(job.key);
        }
        // Results nobody took go in this context, with the precompute's objects.
        std::vector<Result> untaken;
        {
            const std::lock_guard lock(m_mutex);
            untaken.swap(m_results);
        }
    }
    m_context->doneCurrent();
    delete m_context;
}

} // namespace facet
