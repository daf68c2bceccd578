#include "ui/widgets/CacheBudget.h"

#include <QSettings>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <string>

namespace facet {

namespace {

constexpr const char* kSettingKey = "cache/budgetMB";

// FACET_CACHE_BUDGET_MB as a whole number in range, else 0.
int environmentMegabytes()
{
    const char* value = std::getenv("FACET_CACHE_BUDGET_MB");
    if (!value || !*value)
        return 0;
    char* end = nullptr;
    const long megabytes = std::strtol(value, &end, 10);
    if (*end != '\0' || megabytes < CacheBudget::kMinMegabytes || megabytes > CacheBudget::kMaxMegabytes)
        return 0;
    return int(megabytes);
}

// The budget as read or set last; 0 until first read.
std::atomic<int> g_megabytes {0};

int readMegabytes()
{
    if (const int fromEnv = environmentMegabytes(); fromEnv > 0)
        return fromEnv;
    bool ok = false;
    const int stored = QSettings().value(QLatin1String(kSettingKey)).toInt(&ok);
    if (ok && stored >= CacheBudget::kMinMegabytes && stored <= CacheBudget::kMaxMegabytes)
        return stored;
    return CacheBudget::kDefaultMegabytes;
}

} // namespace

int CacheBudget::megabytes()
{
    int megabytes = g_megabytes.load(std::memory_order_relaxed);
    if (megabytes == 0) {
        megabytes = readMegabytes();
        g_megabytes.store(megabytes, std::memory_order_relaxed);
    }
    return megabytes;
}

bool CacheBudget::fromEnvironment()
{
    return environmentMegabytes() > 0;
}

void CacheBudget::setMegabytes(int megabytes)
{
    QSettings().setValue(QLatin1String(kSettingKey), std::clamp(megabytes, kMinMegabytes, kMaxMegabytes));
    g_megabytes.store(readMegabytes(), std::memory_order_relaxed); // the environment still wins
    Q_EMIT instance()->changed(bytes());
}

void CacheBudget::reload()
{
    g_megabytes.store(0, std::memory_order_relaxed);
}

CacheBudget* CacheBudget::instance()
{
    static CacheBudget* budget = new CacheBudget;
    return budget;
}

} // namespace facet
