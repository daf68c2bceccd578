#pragma once
// How much memory the window may keep for what it is not showing, so that going back to it is
// quick (docs/app.md "Memory"): the IBL sets and environment sources of environments shown before
// (render/IblPrecompute's least-recently-used cache: GPU memory, which on a software renderer
// such as llvmpipe is the process's own). What a view shows is always kept, whatever the budget.
//
// The budget is the user's setting (Edit > Preferences, stored with QSettings), or
// FACET_CACHE_BUDGET_MB when that is set (benchmarks, a machine's administrator); kDefaultMegabytes
// otherwise. A change applies at once to every open window's caches.

#include <QObject>

#include <cstddef>

namespace facet {

class CacheBudget : public QObject {
    Q_OBJECT
public:
    // 256 MiB (IblPrecompute::kMemoryBudgetBytes): 12 IBL sets of the high preset (~21 MB each)
    // or 48 of the default (~5.3 MB); a 3x3 environment grid at high quality stays resident.
    static constexpr int kDefaultMegabytes = 256;
    static constexpr int kMinMegabytes = 64;
    static constexpr int kMaxMegabytes = 65536;

    // The budget in MiB: FACET_CACHE_BUDGET_MB (when a whole number in range), else the setting,
    // else kDefaultMegabytes. Read once, then kept (the views ask every frame).
    static int megabytes();
    static std::size_t bytes() { return std::size_t(megabytes()) << 20; }
    // Stores the setting (clamped to the range) and tells every cache (changed()).
    static void setMegabytes(int megabytes);
    // Forgets the kept value: the next megabytes() reads the environment and the setting again
    // (tests that change them).
    static void reload();
    // Whether FACET_CACHE_BUDGET_MB overrides the setting (the preference then says so).
    static bool fromEnvironment();

    // The process-wide notifier.
    static CacheBudget* instance();

Q_SIGNALS:
    void changed(std::size_t bytes);

private:
    CacheBudget() = default;
};

} // namespace facet
