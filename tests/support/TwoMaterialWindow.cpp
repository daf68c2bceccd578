#include "TwoMaterialWindow.h"

#include "ui/document/ProjectFileController.h"
#include "ui/viewport/SceneController.h"

#include "TestAssets.h"

#include <QCoreApplication>

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

    m_window = showTestWindow(m_recovery.path());
    QVERIFY(m_window);
    m_document = m_window->document();
    m_viewport = m_window->viewport();
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

bool TwoMaterialWindowFixture::openTwoMaterials()
{
    return openAndSettle(*m_window, m_twoMaterials) && m_document->project().parts.size() == 2;
}

} // namespace facet::test
