#pragma once
// Hands the memory the window has freed back to the system now and then (core/support/FreedMemory.h):
// every kIntervalMs, when the allocator holds more than kThresholdBytes free and that figure moved
// since the last time (something was freed or reused: a texture set let go after its upload, an
// environment no view shows any more). Without it the window's resident memory climbs with each
// texture set and environment shown although its caches keep to their budget
// (docs/benchmarks.md, "Cache budget"). Made, it also has large blocks mapped on their own
// (core/support/FreedMemory.h mapLargeBlocksOnTheirOwn), which keeps most of that from happening.

#include <QObject>
#include <QTimer>

#include <cstddef>

namespace facet {

class FreedMemoryTimer : public QObject {
    Q_OBJECT
public:
    static constexpr int kIntervalMs = 5000;
    static constexpr std::size_t kThresholdBytes = std::size_t(32) << 20;

    explicit FreedMemoryTimer(QObject* parent = nullptr);

    // Stops (false) or restarts the checks (benchmarks compare the two).
    void setEnabled(bool enabled);
    // One check now (the timer's work): true when memory was handed back.
    bool check();
    // How many checks handed memory back (tests).
    int returns() const { return m_returns; }

private:
    QTimer m_timer;
    std::size_t m_heldAtLastReturn = 0;
    int m_returns = 0;
};

} // namespace facet
