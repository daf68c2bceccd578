// The Compare view's cells converge when the project's IBL method is a sampled one (fis,
// reference), as the single view's still frame does (ui/compare/CompareRenderer.h refineCell,
// FrameRenderer::refine with one slot per cell): every Shaded cell of the environment grid and of
// A/B (whose halves are clipped) reaches its samples, says so in its label, and then the view
// stops drawing; the split sum's cells are not refined; a change of what the samples sum
// (roughness, environment) starts every cell again, a display setting (exposure) does not.
// Needs a display (Xvfb via with-display.sh).

#include "ui/compare/CompareRenderer.h"
#include "ui/compare/CompareView.h"
#include "ui/viewport/SurfaceFormat.h"

#include "CompareTestWindow.h"
#include "TestSupport.h"

#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <algorithm>
#include <functional>

using namespace facet;
using namespace facet::test;

Q_DECLARE_METATYPE(std::function<void(facet::Project&)>)

namespace {

using Edit = std::function<void(Project&)>;

constexpr int kSamples = 16;

Project sampledProject(CompareMode mode, IblMethod method, int samples = kSamples)
{
    Project project = CompareTestWindow::baseProject();
    project.compare.mode = mode;
    project.environment.method = method;
    project.environment.samples = method == IblMethod::SplitSum ? 0 : samples;
    return project;
}

} // namespace

class CompareRefineUiTest : public QObject {
    Q_OBJECT
public:
    static void initMain()
    {
        QStandardPaths::setTestModeEnabled(true);
        installViewportSurfaceFormat();
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_compare.open(m_recovery.path()));
        m_view = m_compare.view();
    }
    void cleanupTestCase() { m_compare.close(); }

    void everyCellConverges_data()
    {
        QTest::addColumn<int>("mode");
        QTest::addColumn<int>("method");
        QTest::addColumn<bool>("refines");
        QTest::newRow("environments, reference")
            << int(CompareMode::Environments) << int(IblMethod::Reference) << true;
        QTest::newRow("environments, fis") << int(CompareMode::Environments) << int(IblMethod::Fis) << true;
        QTest::newRow("a/b, reference") << int(CompareMode::AB) << int(IblMethod::Reference) << true;
        QTest::newRow("environments, split sum")
            << int(CompareMode::Environments) << int(IblMethod::SplitSum) << false;
    }

    void everyCellConverges()
    {
        QFETCH(int, mode);
        QFETCH(int, method);
        QFETCH(bool, refines);
        QVERIFY(m_compare.setProject(sampledProject(CompareMode(mode), IblMethod(method))));
        const CompareRenderer* renderer = m_view->renderer();
        QVERIFY(renderer);
        QVERIFY(!m_view->isRefining());
        const std::size_t cells = m_view->cells().size();
        QVERIFY(cells >= 2);
        const QStringList labels = m_view->cellLabels();
        QCOMPARE(std::size_t(labels.size()), cells);
        for (std::size_t i = 0; i < cells; ++i) {
            const FrameRenderer::Refinement* refinement = renderer->cellRefinement(i);
            if (!refines) {
                QVERIFY2(!refinement, qPrintable(QStringLiteral("cell %1").arg(i)));
                QVERIFY(!labels[int(i)].contains(QStringLiteral("spp")));
                continue;
            }
            QVERIFY2(refinement, qPrintable(QStringLiteral("cell %1 does not refine").arg(i)));
            QVERIFY(refinement->done());
            QCOMPARE(refinement->target, kSamples);
            // Reference may stop early at its noise target; fis runs all of its points.
            QVERIFY(refinement->samples <= kSamples);
            if (IblMethod(method) == IblMethod::Fis)
                QCOMPARE(refinement->samples, kSamples);
            QVERIFY2(
                labels[int(i)].contains(QStringLiteral("/%1 spp").arg(kSamples)), qPrintable(labels[int(i)]));
            QVERIFY2(labels[int(i)].contains(QStringLiteral("(done)")), qPrintable(labels[int(i)]));
        }
        // Converged: no cell is drawn again.
        const std::uint64_t frame = m_view->lastFrameStats().frameNumber;
        QTest::qWait(600);
        QVERIFY(m_view->lastFrameStats().frameNumber == frame || m_view->lastFrameStats().cellsDrawn == 0);
    }

    void restartsOnlyOnWhatItSums_data()
    {
        QTest::addColumn<Edit>("edit");
        QTest::addColumn<bool>("restarts");
        QTest::newRow("roughness") << Edit([](Project& p) {
            p.material().setFactor(MapSlot::Roughness, 0.8);
        }) << true;
        QTest::newRow("environment rotation")
            << Edit([](Project& p) { p.environment.rotationDegrees = 90.0; }) << true;
        QTest::newRow("samples") << Edit([](Project& p) { p.environment.samples = 2 * kSamples; }) << true;
        QTest::newRow("exposure") << Edit([](Project& p) { p.view.exposureEV = 1.0; }) << false;
        QTest::newRow("tone mapper") << Edit([](Project& p) { p.view.toneMapper = ToneMapper::Aces; })
                                     << false;
    }

    void restartsOnlyOnWhatItSums()
    {
        QFETCH(Edit, edit);
        QFETCH(bool, restarts);
        const Project before = sampledProject(CompareMode::Environments, IblMethod::Reference);
        QVERIFY(m_compare.setProject(before));
        const CompareRenderer* renderer = m_view->renderer();
        QVERIFY(renderer && renderer->cellRefinement(0) && renderer->cellRefinement(0)->done());
        // The fewest samples any cell showed in a frame after the edit: 0 after a restart.
        int fewest = 1 << 30;
        const QMetaObject::Connection watch = connect(m_view, &CompareView::frameRendered, this, [&] {
            for (std::size_t i = 0; i < m_view->cells().size(); ++i)
                if (const FrameRenderer::Refinement* r = m_view->renderer()->cellRefinement(i))
                    fewest = std::min(fewest, r->samples);
        });
        Project after = before;
        edit(after);
        QVERIFY(m_compare.setProject(after));
        disconnect(watch);
        QVERIFY(fewest < (1 << 30)); // a frame was drawn
        const FrameRenderer::Refinement* refinement = renderer->cellRefinement(0);
        QVERIFY(refinement && refinement->done());
        QCOMPARE(fewest < refinement->samples, restarts);
    }

private:
    QTemporaryDir m_recovery;
    CompareTestWindow m_compare;
    CompareView* m_view = nullptr;
};

QTEST_MAIN(CompareRefineUiTest)
#include "CompareRefineUiTest.moc"
