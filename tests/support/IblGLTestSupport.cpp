#include "IblGLTestSupport.h"

#include <QString>
#include <QtTest/QTest>

#include <string>

namespace facet::test {

IblSettings smallSettings()
{
    IblSettings s;
    s.cubeSize = 32;
    s.prefilterSize = 16;
    s.prefilterMipLevels = 5;
    s.prefilterSamples = 64;
    s.irradianceSize = 8;
    s.irradianceSamples = 384; // 8x8 texels a face
    s.dfgSize = 16;
    s.dfgSamples = 128;
    return s;
}

Level readLevel(const std::shared_ptr<const GLTexture>& texture, int face, int level)
{
    Level out;
    out.rgba = readTextureLevel(*texture, face, level, &out.width, &out.height);
    return out;
}

void IblGLFixture::initIblFixture()
{
    std::string error;
    m_context = HeadlessGLContext::create(&error);
    QVERIFY2(m_context, error.c_str());
    QVERIFY(m_cacheDir.isValid());
    qputenv("FACET_CACHE_DIR", m_cacheDir.path().toUtf8());
    // Memory cache only for the accuracy tests (they run each environment once).
    m_ibl.emplace(QString(), false);
}

void IblGLFixture::cleanupIblFixture()
{
    m_ibl.reset(); // GL objects go with the context current
    m_context.reset();
}

} // namespace facet::test
