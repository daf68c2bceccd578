#pragma once
// The GPU resources the views of one window share (not a widget): the IBL precompute, and so every
// IBL set and DFG table (render/IblPrecompute), and the material textures (render/TextureCache).
// Every QOpenGLWidget of a top-level window shares its context with the others (Qt makes them one
// share group), so the single view and the Compare view draw with one set of textures: an
// environment shown by the single view and by four grid cells is precomputed once, and a 2K
// texture set is uploaded once, whichever view shows it first.
//
// The group also has the window's lighting worker (ui/viewport/LightingWorker): the IBL precompute of a
// new environment runs on its thread, in a context of the group, while the views draw on.
//
// A view asks for the resources when it makes its renderer (initializeGL, its context current).
// The group keeps them weakly: they live while a view's renderer holds them and go with the last
// one, in that view's context, which is one of the group's. A view whose context does not share
// with the group's (a context made elsewhere) gets resources of its own.

#include <QPointer>

#include <memory>

class QOpenGLContextGroup;

namespace facet {

class IblPrecompute;
class LightingWorker;
class TextureCache;

class ViewShareGroup {
public:
    // `useDiskCache` false: the IBL results stay in memory (tests never touch the user's cache).
    explicit ViewShareGroup(bool useDiskCache = true);
    // For the resources made from now on (tests set it before the window is first shown).
    void setUseDiskCache(bool use) { m_useDiskCache = use; }
    bool useDiskCache() const { return m_useDiskCache; }

    struct Resources {
        std::shared_ptr<IblPrecompute> precompute;
        std::shared_ptr<TextureCache> textures;
        // Null where the platform cannot run GL on a second thread: the view then precomputes
        // on the GUI thread.
        std::shared_ptr<LightingWorker> lighting;
        bool shared = false; // another view's: its contexts share with the current one
    };
    // With a view's context current: the resources of the views that asked before, when they are
    // still alive and their contexts share with the current one; otherwise new ones (kept for the
    // views that ask next).
    Resources acquire();

    // How many times acquire() made new resources (tests: two views of a window make them once).
    int resourcesMade() const { return m_made; }

private:
    bool m_useDiskCache = true;
    QPointer<QOpenGLContextGroup> m_group;
    std::weak_ptr<IblPrecompute> m_precompute;
    std::weak_ptr<TextureCache> m_textures;
    std::weak_ptr<LightingWorker> m_lighting;
    int m_made = 0;
};

} // namespace facet
