#pragma once
// The assets of the Compare view's cells that the single view does not already hold (not a
// widget, no GL): environments by spec, each decoded once (Environment::fromSpec on a worker
// thread, a QThreadPool), and material maps a cell names that the project's SceneController has
// not loaded (an A/B snapshot whose file the current material no longer uses), decoded through
// the process-wide core/MapImageCache, so a file the single view holds is shared, never decoded
// twice. Until an asset arrives the cell says "Loading <name>…"; each arrival is announced
// (assetArrived) and the view redraws the cells that waited for it.
//
// Environments are kept while a cell shows them: release() drops the ones no cell names.

#include "core/Environment.h"
#include "core/MapImage.h"

#include <QObject>
#include <QString>
#include <QThreadPool>

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>

namespace facet {

class CompareAssets : public QObject {
    Q_OBJECT
public:
    explicit CompareAssets(QObject* parent = nullptr);
    ~CompareAssets() override; // drops queued loads, waits for running ones

    // The environment `spec` names at rotation 0 and intensity 1 (a copy shares its pixels: set
    // the cell's rotation and intensity on it), or null while it loads (the first call starts the
    // load) or when it could not be read (problem() says why).
    std::shared_ptr<const Environment> environment(const std::string& spec);
    // Why `spec` could not be loaded (Environment::fromSpec's message); empty otherwise.
    std::string problem(const std::string& spec) const;
    bool isLoading(const std::string& spec) const { return m_loading.count(spec) > 0; }

    // The map image of `path`, or null while it decodes (the first call starts it) or when it
    // could not be read.
    std::shared_ptr<const MapImage> map(const std::string& path);

    // Drops the environments and maps not in `keep` (specs and paths a cell shows).
    void release(const std::set<std::string>& keep);

    // How many environment decodes ran (tests: "each environment once").
    int environmentLoads() const { return m_environmentLoads; }
    int pendingLoads() const { return int(m_loading.size()); }
    // Blocks until every queued load finished (tests and the benchmark), then delivers them.
    void waitForLoads();

Q_SIGNALS:
    // An environment or a map finished loading (or failed): the cells that wait for it redraw.
    void assetArrived();

private:
    struct Result {
        std::shared_ptr<const Environment> environment;
        std::shared_ptr<const MapImage> map;
        std::string error;
    };
    // Runs `load` on a worker unless `key` is loading or failed (false then); the result comes
    // back through deliver() on this object's thread.
    bool startLoad(const std::string& key, std::function<Result()> load);
    void deliver(const std::string& key, Result result);

    std::map<std::string, std::shared_ptr<const Environment>> m_environments;
    std::map<std::string, std::shared_ptr<const MapImage>> m_maps;
    std::map<std::string, std::string> m_problems;
    std::set<std::string> m_loading; // keys: "env:" + spec or "map:" + path
    int m_environmentLoads = 0;
    QThreadPool m_pool; // declared last: destroyed (waited for) first
};

} // namespace facet
