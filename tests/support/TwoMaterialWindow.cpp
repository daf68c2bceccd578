#include "TwoMaterialWindow.h"

#include "ui/document/ProjectFileController.h"
#include "ui/viewport/SceneController.h"

#include "TestAssets.h"

#include <QCoreApplication>
#include <QMessageBox>
#include <QSignalSpy>

namespace facet::test {

void TwoMaterialWindowFixture::initWindowFixture()
{
    QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
    QVERIFY(m_dir.isValid());
    m_twoMaterials = m_dir.filePath(QStringLiteral("two.glb"));
    m_translucent = m_dir.filePath(QStringLiteral("translucent.glb"));
    QString error;
    QVERIFY2(writeTwoMaterialAsset(m_twoMaterials, &error), qPrintable(error));
    QVERIFY2(writeTwoMaterialAsset(m_translucent, &error, 0.3), qPrintable(error));

    m_window = std::make_unique<MainWindow>(nullptr, m_recovery.path());
    m_document = m_window->document();
    m_viewport = m_window->viewport();
    m_window->projectFiles()->setErrorDialogsEnabled(false);
    m_window->projectFiles()->setUnsavedChangesAnswer(QMessageBox::Discard);
    QSignalSpy rendered(m_viewport, &ViewportWidget::frameRendered);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QVERIFY(rendered.count() > 0 || rendered.wait(60000));
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
}

void TwoMaterialWindowFixture::cleanupWindowFixture()
{
    m_document->newProject();
    m_window.reset();
}

bool TwoMaterialWindowFixture::open(const QString& path)
{
    if (!m_window->projectFiles()->openFile(path))
        return false;
    SceneController* scene = m_window->sceneController();
    return QTest::qWaitFor([scene] { return scene->pendingAssetLoads() == 0; }, 30000);
}

} // namespace facet::test
