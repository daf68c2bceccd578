#pragma once
// What the IBL precompute's GL tests share (IblGLTest, IblCacheGLTest): settings small enough for
// llvmpipe on 2 cores, a texture level read back, and their fixture (a headless GL context, a
// temporary $FACET_CACHE_DIR and a precompute with a memory cache only). Compiled into those
// tests only.

#include "render/GLTexture.h"
#include "render/HeadlessGLContext.h"
#include "render/IblPrecompute.h"
#include "render/IblSettings.h"

#include <QTemporaryDir>

#include <glm/vec3.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace facet::test {

// Small settings for tests on llvmpipe.
IblSettings smallSettings();

struct Level {
    int width = 0;
    int height = 0;
    std::vector<float> rgba;
    glm::dvec3 at(int x, int y) const
    {
        const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
        return {rgba[i], rgba[i + 1], rgba[i + 2]};
    }
};

Level readLevel(const std::shared_ptr<const GLTexture>& texture, int face, int level);

// The tests' state, a base of each test class: initIblFixture() is its initTestCase (it fails
// the test case when there is no context), cleanupIblFixture() its cleanupTestCase.
class IblGLFixture {
protected:
    void initIblFixture();
    void cleanupIblFixture();

    std::optional<HeadlessGLContext> m_context;
    QTemporaryDir m_cacheDir;
    std::optional<IblPrecompute> m_ibl;
};

} // namespace facet::test
