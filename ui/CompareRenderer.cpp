// Includes epoxy (render/'s GL loader) and no Qt GL header: the two must not meet in one file.
#include <epoxy/gl.h>

#include "ui/CompareRenderer.h"

#include "core/ToneMap.h"
#include "render/IblSettings.h"
#include "render/Renderer.h"
#include "render/SceneFromProject.h"
#include "render/TextureCache.h"
#include "render/TextureFiltering.h"

#include <QElapsedTimer>

#include <algorithm>
#include <set>

namespace facet {

namespace {

IblSettings iblSettingsOf(const Project& project)
{
    return IblSettings::preset(toString(project.environment.quality)).value_or(IblSettings {});
}

} // namespace

CompareRenderer::CompareRenderer(const QString& cacheDirectory, bool useDiskCache)
    : m_frames(std::make_unique<FrameRenderer>(cacheDirectory, useDiskCache))
    , m_glInfo(queryCurrentGLInfo())
{
}

CompareRenderer::CompareRenderer(
    std::shared_ptr<IblPrecompute> precompute, std::shared_ptr<TextureCache> textures)
    : m_frames(std::make_unique<FrameRenderer>(std::move(precompute), std::move(textures)))
    , m_glInfo(queryCurrentGLInfo())
{
}

CompareRenderer::~CompareRenderer()
{
    // GL objects go while the caller holds the context current: textures first, then their makers.
    m_lighting.clear();
    m_composite.reset();
    m_scratch.reset();
    m_frames.reset();
}

void CompareRenderer::invalidate()
{
    m_drawn.clear();
}

void CompareRenderer::touchMaps(const CompareCellDraw& cell)
{
    TextureCache& textures = m_frames->textureCache();
    for (std::size_t m = 0; m < cell.assets.maps.size() && m < cell.project.materials.size(); ++m)
        for (MapSlot slot : kAllMapSlots) {
            const LoadedMapImage& map = cell.assets.maps[m][std::size_t(slot)];
            if (map.image && !map.path.empty())
                textures.touch(map.path, map.timestamp, cell.project.materials[m].map(slot).colorSpace);
        }
}

bool CompareRenderer::textureReady(
    const std::string& path, std::int64_t timestamp, ColorEncoding colorSpace) const
{
    return m_frames->textureCache().isReady(path, timestamp, colorSpace);
}

CompareRenderer::CellKey CompareRenderer::keyOf(const CompareCellDraw& cell, double scale)
{
    CellKey key;
    key.project = cell.project;
    if (!cell.assets.environment.isEmpty())
        key.environmentPixels = &cell.assets.environment.image();
    key.environmentRotation = cell.assets.environment.rotationDegrees();
    key.environmentIntensity = cell.assets.environment.intensity();
    for (const auto& material : cell.assets.maps)
        for (const LoadedMapImage& map : material)
            key.maps.push_back(map.image.get());
    key.mesh = cell.assets.mesh.get();
    key.rect[0] = cell.rect.x;
    key.rect[1] = cell.rect.y;
    key.rect[2] = cell.rect.width;
    key.rect[3] = cell.rect.height;
    if (cell.clip) {
        key.clip[0] = cell.clip->x;
        key.clip[1] = cell.clip->y;
        key.clip[2] = cell.clip->width;
        key.clip[3] = cell.clip->height;
    }
    key.scale = scale;
    return key;
}

float CompareRenderer::displayGrey(float linear)
{
    return float(tonemap::linearToSrgb(double(linear)));
}

void CompareRenderer::fill(const FrameRect& rect, float grey)
{
    m_composite->bind();
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect.x, rect.y, rect.width, rect.height);
    const float value = displayGrey(grey);
    glClearColor(value, value, value, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

std::pair<std::uint64_t, std::uint64_t> CompareRenderer::lightingKeyOf(const CompareCellDraw& cell)
{
    // By content, not by the image's address: an environment freed after one frame and another
    // made at the same address before the next must not find the first one's lighting (the
    // grid showed a cell lit by the previous environment; CompareUiTest's prepared-once row
    // counted one request for two environments when that happened).
    return std::make_pair(cell.assets.environment.contentHash(), iblSettingsOf(cell.project).hash());
}

bool CompareRenderer::needsLighting(const CompareCellDraw& cell) const
{
    // A set the shared precompute holds (the single view's environment, a grid shown before) is
    // a memory hit: nothing to announce.
    return !cell.assets.environment.isEmpty() && !m_lighting.count(lightingKeyOf(cell))
        && !m_frames->precompute().holds(cell.assets.environment, iblSettingsOf(cell.project));
}

int CompareRenderer::lightingToPrepare(const std::vector<CompareCellDraw>& cells) const
{
    std::set<std::pair<std::uint64_t, std::uint64_t>> keys;
    for (const CompareCellDraw& cell : cells)
        if (needsLighting(cell))
            keys.insert(lightingKeyOf(cell));
    return int(keys.size());
}

std::shared_ptr<const IblTextures> CompareRenderer::lightingFor(
    const CompareCellDraw& cell, std::string* error)
{
    const IblSettings settings = iblSettingsOf(cell.project);
    const auto key = lightingKeyOf(cell);
    if (const auto found = m_lighting.find(key); found != m_lighting.end())
        return found->second;
    IblStats stats;
    auto ibl = m_frames->lighting(cell.assets.environment, settings, &stats, error);
    ++m_stats.iblRequests;
    if (stats.passesRun > 0)
        ++m_stats.iblComputed;
    else if (stats.cacheHitsDisk > 0)
        ++m_stats.iblFromDisk;
    m_stats.iblMs += stats.msTotal;
    if (ibl)
        m_lighting.emplace(key, ibl);
    return ibl;
}

bool CompareRenderer::drawCell(const CompareCellDraw& cell, double scale, std::string* error)
{
    if (cell.assets.environment.isEmpty()) {
        fill(cell.rect, kLoadingGrey);
        ++m_stats.cellsLoading;
        touchMaps(cell); // shown as soon as its environment arrives
        return true;
    }
    if (cell.clip && (cell.clip->width <= 0 || cell.clip->height <= 0))
        return true; // the divider at the edge: nothing of this side shows
    const auto ibl = lightingFor(cell, error);
    if (!ibl)
        return false;
    const IblSettings settings = iblSettingsOf(cell.project);
    SceneOptions options = sceneOptionsFor(settings, false);
    options.iblMethod = IblMethod::SplitSum; // the window's preview (SceneOptions::iblMethod)
    RenderScene scene = sceneFromProject(cell.project, cell.assets, ibl, options);
    IblStats dfgStats;
    if (!m_frames->addDfgTables(settings, scene, &dfgStats, error))
        return false;
    m_stats.iblMs += dfgStats.msTotal;
    if (!cell.clip) {
        const bool presented
            = m_frames->present(scene, m_composite->framebufferId(), cell.rect, scale, error);
        m_stats.texturesUploaded += m_frames->renderer().lastFrameStats().texturesUploaded;
        return presented;
    }

    // Rendered whole at the cell's size, then only the clipped part copied: the two sides of a
    // split come from images of one size and camera, so they meet without a seam or a shift.
    if (!m_scratch || m_scratch->width() != cell.rect.width || m_scratch->height() != cell.rect.height) {
        m_scratch.reset();
        m_scratch = Framebuffer::create(cell.rect.width, cell.rect.height, FramebufferFormat::RGBA16F, error);
        if (!m_scratch)
            return false;
    }
    const bool presented = m_frames->present(
        scene, m_scratch->framebufferId(), FrameRect {0, 0, cell.rect.width, cell.rect.height}, scale, error);
    m_stats.texturesUploaded += m_frames->renderer().lastFrameStats().texturesUploaded;
    if (!presented)
        return false;
    const FrameRect& clip = *cell.clip;
    const int sx = clip.x - cell.rect.x;
    const int sy = clip.y - cell.rect.y;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_scratch->framebufferId());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_composite->framebufferId());
    glBlitFramebuffer(sx, sy, sx + clip.width, sy + clip.height, clip.x, clip.y, clip.x + clip.width,
        clip.y + clip.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    return true;
}

bool CompareRenderer::paint(const std::vector<CompareCellDraw>& cells, unsigned targetFramebuffer, int width,
    int height, double scale, std::string* error)
{
    QElapsedTimer clock;
    clock.start();
    m_stats.iblMs = 0.0;
    m_stats.cellsDrawn = 0;
    m_stats.cellsKept = 0;
    m_stats.cellsLoading = 0;
    scale = std::clamp(scale, 0.05, 1.0);
    std::string problem;
    if (!m_composite || m_composite->width() != width || m_composite->height() != height) {
        m_composite.reset();
        m_composite = Framebuffer::create(
            std::max(width, 1), std::max(height, 1), FramebufferFormat::RGBA16F, &problem);
        if (!m_composite) {
            *error = "CompareRenderer::paint: " + problem;
            return false;
        }
        m_drawn.clear();
    }
    std::vector<FrameRect> rects;
    rects.reserve(cells.size());
    for (const CompareCellDraw& cell : cells)
        rects.push_back(cell.rect);
    const auto sameRect = [](const FrameRect& a, const FrameRect& b) {
        return a.x == b.x && a.y == b.y && a.width == b.width && a.height == b.height;
    };
    if (m_drawn.size() != cells.size()
        || !std::equal(rects.begin(), rects.end(), m_rects.begin(), m_rects.end(), sameRect)) {
        // Another set of cells or another arrangement of them (a mode switch, a cell added, the
        // wedge's axis margins): the gaps and the free part of the grid are new too, and nothing
        // drawn before may show through them.
        m_drawn.assign(cells.size(), std::nullopt);
        const float gap = displayGrey(kGapGrey);
        m_composite->clear(glm::vec4(gap, gap, gap, 1.0f));
        m_rects = std::move(rects);
    }
    const bool reduced = scale < 1.0;
    m_frames->textureCache().setMaxAnisotropy(TextureFiltering::anisotropyFor(m_glInfo, reduced));

    bool ok = true;
    std::set<std::pair<std::uint64_t, std::uint64_t>> shown;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const CompareCellDraw& cell = cells[i];
        if (!cell.assets.environment.isEmpty())
            shown.insert(lightingKeyOf(cell));
        CellKey key = keyOf(cell, scale);
        if (m_drawn[i] && *m_drawn[i] == key) {
            ++m_stats.cellsKept;
            touchMaps(cell); // still shown: its textures stay
            continue;
        }
        std::string cellProblem;
        if (drawCell(cell, scale, &cellProblem)) {
            m_drawn[i] = std::move(key);
            ++m_stats.cellsDrawn;
        } else {
            fill(cell.rect, kLoadingGrey);
            m_drawn[i].reset();
            if (ok)
                *error = "CompareRenderer::paint: " + cellProblem;
            ok = false;
        }
    }
    // The IBL sets no cell shows any more go (FrameRenderer's memory cache may keep them).
    std::erase_if(m_lighting, [&shown](const auto& entry) { return !shown.count(entry.first); });
    // Textures no cell shows go: those of the cells drawn were used, those of kept cells and of
    // cells waiting for their environment were touched (they must stay, or the next redraw would
    // upload them again, from a decoded copy the single view may have released).
    if (ok)
        m_frames->finishFrame();
    m_stats.texturesResident = int(m_frames->textureCache().size());

    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_composite->framebufferId());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targetFramebuffer);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, targetFramebuffer);
    glViewport(0, 0, width, height);
    // Honest frame times: wait for the GPU (llvmpipe renders on the CPU anyway).
    glFinish();
    ++m_stats.frameNumber;
    m_stats.reduced = reduced;
    m_stats.frameMs = double(clock.nsecsElapsed()) / 1e6 - m_stats.iblMs;
    return ok;
}

} // namespace facet
