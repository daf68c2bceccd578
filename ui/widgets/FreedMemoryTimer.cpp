#include "ui/widgets/FreedMemoryTimer.h"

#include "core/support/FreedMemory.h"

namespace facet {

FreedMemoryTimer::FreedMemoryTimer(QObject* parent)
    : QObject(parent)
{
    mapLargeBlocksOnTheirOwn();
    m_timer.setInterval(kIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &FreedMemoryTimer::check);
    m_timer.start();
}

void FreedMemoryTimer::setEnabled(bool enabled)
{
    if (enabled)
        m_timer.start();
    else
        m_timer.stop();
}

bool FreedMemoryTimer::check()
{
    const std::size_t held = freedMemoryHeld();
    if (held <= kThresholdBytes || held == m_heldAtLastReturn)
        return false;
    m_heldAtLastReturn = held;
    if (!returnFreedMemory())
        return false;
    ++m_returns;
    return true;
}

} // namespace facet
