#include "ui/viewport/ViewShareGroup.h"

#include "render/IblPrecompute.h"
#include "render/TextureCache.h"
#include "ui/viewport/LightingWorker.h"

#include <QDebug>
#include <QOpenGLContext>
#include <QOpenGLContextGroup>

namespace facet {

ViewShareGroup::ViewShareGroup(bool useDiskCache)
    : m_useDiskCache(useDiskCache)
{
}

ViewShareGroup::Resources ViewShareGroup::acquire()
{
    QOpenGLContext* context = QOpenGLContext::currentContext();
    QOpenGLContextGroup* group = context ? context->shareGroup() : nullptr;
    Resources resources;
    if (group && group == m_group) {
        resources.precompute = m_precompute.lock();
        resources.textures = m_textures.lock();
        resources.lighting = m_lighting.lock();
    }
    resources.shared = resources.precompute && resources.textures;
    if (resources.shared)
        return resources;
    // The first view, or the others have gone (their GL objects with them): make new ones.
    resources.precompute = std::make_shared<IblPrecompute>(QString(), m_useDiskCache);
    resources.textures = std::make_shared<TextureCache>();
    auto lighting = std::make_shared<LightingWorker>(QString(), m_useDiskCache);
    if (lighting->isValid())
        resources.lighting = std::move(lighting);
    else
        qInfo().noquote() << "Facet: the lighting is precomputed on the GUI thread:" << lighting->problem();
    m_group = group;
    m_precompute = resources.precompute;
    m_textures = resources.textures;
    m_lighting = resources.lighting;
    ++m_made;
    return resources;
}

} // namespace facet
