#include "ui/CompareAssets.h"

#include "core/MapImageCache.h"

#include <QCoreApplication>
#include <QDebug>
#include <QMetaObject>
#include <QPointer>
#include <QThread>

#include <algorithm>

namespace facet {

namespace {

std::string environmentKey(const std::string& spec)
{
    return "env:" + spec;
}

std::string mapKey(const std::string& path)
{
    return "map:" + path;
}

} // namespace

CompareAssets::CompareAssets(QObject* parent)
    : QObject(parent)
{
    // Decoding beside llvmpipe's threads and the GUI thread (SceneController's rule): leave a core.
    m_pool.setMaxThreadCount(std::clamp(QThread::idealThreadCount() - 1, 1, 4));
}

CompareAssets::~CompareAssets()
{
    m_pool.clear();
    m_pool.waitForDone();
}

std::shared_ptr<const Environment> CompareAssets::environment(const std::string& spec)
{
    if (const auto found = m_environments.find(spec); found != m_environments.end())
        return found->second;
    const bool started = startLoad(environmentKey(spec), [spec] {
        Result result;
        std::string warning;
        if (std::optional<Environment> loaded = Environment::fromSpec(spec, &result.error, &warning))
            result.environment = std::make_shared<const Environment>(std::move(*loaded));
        if (!warning.empty())
            qWarning().noquote() << "facet:" << QString::fromStdString(warning);
        return result;
    });
    if (started)
        ++m_environmentLoads;
    return nullptr;
}

std::string CompareAssets::problem(const std::string& spec) const
{
    const auto found = m_problems.find(environmentKey(spec));
    return found == m_problems.end() ? std::string() : found->second;
}

std::shared_ptr<const MapImage> CompareAssets::map(const std::string& path)
{
    if (const auto found = m_maps.find(path); found != m_maps.end())
        return found->second;
    startLoad(mapKey(path), [path] {
        Result result;
        result.map = MapImageCache::shared().load(path, &result.error);
        return result;
    });
    return nullptr;
}

bool CompareAssets::startLoad(const std::string& key, std::function<Result()> load)
{
    if (m_problems.count(key) || m_loading.count(key))
        return false;
    m_loading.insert(key);
    QPointer<CompareAssets> self(this);
    m_pool.start([self, key, load = std::move(load)] {
        const Result result = load();
        QMetaObject::invokeMethod(
            self.data(),
            [self, key, result] {
                if (self)
                    self->deliver(key, result);
            },
            Qt::QueuedConnection);
    });
    return true;
}

void CompareAssets::deliver(const std::string& key, Result result)
{
    m_loading.erase(key);
    const bool isEnvironment = key.rfind("env:", 0) == 0;
    const std::string name = key.substr(4);
    if (!result.error.empty() || (isEnvironment ? !result.environment : !result.map)) {
        qWarning().noquote() << "facet: Compare:" << QString::fromStdString(result.error);
        m_problems[key] = result.error.empty() ? "could not be loaded" : result.error;
    } else if (isEnvironment) {
        m_environments[name] = std::move(result.environment);
    } else {
        m_maps[name] = std::move(result.map);
    }
    Q_EMIT assetArrived();
}

void CompareAssets::release(const std::set<std::string>& keep)
{
    std::erase_if(m_environments, [&keep](const auto& entry) { return !keep.count(entry.first); });
    std::erase_if(m_maps, [&keep](const auto& entry) { return !keep.count(entry.first); });
    // A file that failed is tried again when a cell names it again (it may have been fixed).
    std::erase_if(m_problems, [&keep](const auto& entry) { return !keep.count(entry.first.substr(4)); });
}

void CompareAssets::waitForLoads()
{
    m_pool.waitForDone();
    QCoreApplication::sendPostedEvents(this);
}

} // namespace facet
