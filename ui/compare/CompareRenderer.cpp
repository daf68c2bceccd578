// Includes epoxy (render/'s GL loader) and no Qt GL header: the two must not meet in one file.
#include <epoxy/gl.h>

#include "ui/compare/CompareRenderer.h"

#include "core/image/ToneMap.h"
#include "render/IblSettings.h"
#include "render/Renderer.h"
#include "render/SceneFromProject.h"
#include "render/TextureCache.h"
#include "render/TextureFiltering.h"

#include "core/image/HeatMap.h"
#include "ui/viewport/ViewportRenderer.h"
#include "ui/widgets/CacheBudget.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFontMetrics>
#include <QImage>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <set>

namespace facet {

namespace {
// FrameRenderer::refine's slot of the error view's reference; Shaded cells use their index.
constexpr int kErrorSlot = -1;
} // namespace

namespace {

IblSettings iblSettingsOf(const Project& project)
{
    return IblSettings::preset(project.environment.quality);
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
        key.environmentHash = cell.assets.environment.contentHash();
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
    countLighting(stats);
    m_stats.iblMs += stats.msTotal;
    if (ibl)
        m_lighting.emplace(key, ibl);
    return ibl;
}

void CompareRenderer::countLighting(const IblStats& stats)
{
    if (stats.passesRun > 0)
        ++m_stats.iblComputed;
    else if (stats.cacheHitsDisk > 0)
        ++m_stats.iblFromDisk;
}

IblSettings CompareRenderer::lightingSettingsOf(const CompareCellDraw& cell)
{
    return iblSettingsOf(cell.project);
}

void CompareRenderer::adoptLighting(
    std::uint64_t key, std::shared_ptr<const IblTextures> textures, const IblStats& stats)
{
    m_frames->precompute().adopt(key, std::move(textures));
    countLighting(stats);
    ++m_stats.iblFromWorker;
}

std::optional<RenderScene> CompareRenderer::sceneOf(
    const CompareCellDraw& cell, std::optional<IblMethod> method, std::string* error)
{
    const auto ibl = lightingFor(cell, error);
    if (!ibl)
        return std::nullopt;
    const IblSettings settings = iblSettingsOf(cell.project);
    SceneOptions options = sceneOptionsFor(settings, false);
    options.iblMethod = method;
    IblStats stats;
    std::optional<RenderScene> scene
        = m_frames->prepare(cell.project, cell.assets, settings, options, &stats, error, ibl);
    m_stats.iblMs += stats.msTotal;
    return scene;
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
    // The window's preview (SceneOptions::iblMethod): the split sum.
    const std::optional<RenderScene> prepared = sceneOf(cell, IblMethod::SplitSum, error);
    if (!prepared)
        return false;
    const RenderScene& scene = *prepared;
    if (!cell.clip) {
        const bool presented
            = m_frames->present(scene, m_composite->framebufferId(), cell.rect, scale, error);
        m_stats.texturesUploaded += m_frames->renderer().lastFrameStats().texturesUploaded;
        return presented;
    }

    // Rendered whole at the cell's size, then only the clipped part copied: the two sides of a
    // split come from images of one size and camera, so they meet without a seam or a shift.
    Framebuffer* scratch = scratchFor(cell, error);
    if (!scratch)
        return false;
    const bool presented = m_frames->present(
        scene, scratch->framebufferId(), FrameRect {0, 0, cell.rect.width, cell.rect.height}, scale, error);
    m_stats.texturesUploaded += m_frames->renderer().lastFrameStats().texturesUploaded;
    if (!presented)
        return false;
    copyClip(cell);
    return true;
}

Framebuffer* CompareRenderer::scratchFor(const CompareCellDraw& cell, std::string* error)
{
    if (!m_scratch || m_scratch->width() != cell.rect.width || m_scratch->height() != cell.rect.height) {
        m_scratch.reset();
        m_scratch = Framebuffer::create(cell.rect.width, cell.rect.height, FramebufferFormat::RGBA16F, error);
    }
    return m_scratch ? &*m_scratch : nullptr;
}

void CompareRenderer::copyClip(const CompareCellDraw& cell)
{
    const FrameRect& clip = *cell.clip;
    const int sx = clip.x - cell.rect.x;
    const int sy = clip.y - cell.rect.y;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_scratch->framebufferId());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_composite->framebufferId());
    glBlitFramebuffer(sx, sy, sx + clip.width, sy + clip.height, clip.x, clip.y, clip.x + clip.width,
        clip.y + clip.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

bool CompareRenderer::refineCell(
    const CompareCellDraw& cell, std::size_t index, bool restart, double drawBudgetMs, std::string* error)
{
    const std::optional<RenderScene> preview = sceneOf(cell, IblMethod::SplitSum, error);
    const std::optional<RenderScene> sampled
        = preview ? sceneOf(cell, cell.project.environment.method, error) : std::nullopt;
    if (!sampled)
        return false;
    const int slot = int(index);
    int& drawSamples = m_cellDrawSamples[index];
    if (restart)
        drawSamples = 1;
    unsigned framebuffer = m_composite->framebufferId();
    FrameRect rect = cell.rect;
    if (cell.clip) {
        const Framebuffer* scratch = scratchFor(cell, error);
        if (!scratch)
            return false;
        framebuffer = scratch->framebufferId();
        rect = FrameRect {0, 0, cell.rect.width, cell.rect.height};
    }
    if (!m_frames->refine(*preview, *sampled, framebuffer, rect, restart, drawSamples, error, slot))
        return false;
    m_stats.texturesUploaded += m_frames->renderer().lastFrameStats().texturesUploaded;
    const FrameRenderer::Refinement& state = m_frames->refinement(slot);
    if (!restart && state.draws > 0)
        drawSamples
            = ViewportRenderer::nextDrawSamples(state.lastDrawSamples, state.lastDrawMs, drawBudgetMs);
    if (cell.clip)
        copyClip(cell);
    return true;
}

const FrameRenderer::Refinement* CompareRenderer::cellRefinement(std::size_t index) const
{
    if (index >= m_accumulated.size() || !m_accumulated[index])
        return nullptr;
    return &m_frames->refinement(int(index));
}

namespace {

// The heat map's legend, along the bottom of the cell: the colour ramp from 0 to `scale`, its
// ends and middle in percent, and what is off the scale.
void paintLegend(QImage& image, double scale, bool noise)
{
    const int margin = 8;
    const int barHeight = 10;
    const int width = std::min(image.width() - 2 * margin, 320);
    if (width < 60 || image.height() < 60)
        return;
    QPainter painter(&image);
    painter.setRenderHint(QPainter::TextAntialiasing);
    QFont font = painter.font();
    font.setPixelSize(11);
    painter.setFont(font);
    const int textHeight = QFontMetrics(font).height();
    const int top = image.height() - margin - barHeight - textHeight - 4;
    painter.fillRect(
        QRect(margin - 4, top - 4, width + 8 + 24, barHeight + textHeight + 12), QColor(0, 0, 0, 150));
    for (int x = 0; x < width; ++x) {
        const glm::vec3 c = heatmap::ramp(double(x) / double(std::max(width - 1, 1)));
        painter.fillRect(QRect(margin + x, top, 1, barHeight), QColor::fromRgbF(c.r, c.g, c.b));
    }
    const glm::vec3 over = heatmap::kOverScale;
    painter.fillRect(QRect(margin + width + 4, top, 16, barHeight), QColor::fromRgbF(over.r, over.g, over.b));
    painter.setPen(Qt::white);
    const auto percent = [](double value) { return QStringLiteral("%1%").arg(value * 100.0, 0, 'g', 3); };
    const int textTop = top + barHeight + 2;
    painter.drawText(QRect(margin, textTop, width, textHeight), Qt::AlignLeft, QStringLiteral("0"));
    painter.drawText(QRect(margin, textTop, width, textHeight), Qt::AlignHCenter,
        (noise ? QCoreApplication::translate("CompareRenderer", "noise %1")
               : QCoreApplication::translate("CompareRenderer", "error %1"))
            .arg(percent(scale / 2.0)));
    painter.drawText(QRect(margin, textTop, width, textHeight), Qt::AlignRight, percent(scale));
    painter.drawText(QRect(margin + width + 2, textTop, 24, textHeight), Qt::AlignLeft, QStringLiteral(">"));
}

} // namespace

bool CompareRenderer::isRefining() const
{
    return (m_stats.error && !m_stats.error->done()) || m_stats.cellsRefining > 0;
}

bool CompareRenderer::drawHeatMap(
    const CompareCellDraw& heat, const std::vector<float>& values, std::string* error)
{
    const FrameRect& rect = heat.rect;
    const ErrorCompare& settings = heat.project.compare.error;
    QImage image(rect.width, rect.height, QImage::Format_RGBA8888);
    // Outside the object: the gap's grey, a shade lighter, so the mask's outline shows.
    const int outside = int(std::lround(displayGrey(kGapGrey * 2.0f) * 255.0f));
    image.fill(QColor(outside, outside, outside));
    if (values.size() == std::size_t(rect.width) * std::size_t(rect.height))
        for (int y = 0; y < rect.height; ++y) {
            auto* line = reinterpret_cast<std::uint8_t*>(image.scanLine(y));
            for (int x = 0; x < rect.width; ++x) {
                const float value = values[std::size_t(y) * std::size_t(rect.width) + std::size_t(x)];
                if (std::isnan(value))
                    continue;
                const glm::vec3 c = heatmap::color(double(value), settings.scale);
                line[4 * x + 0] = std::uint8_t(std::lround(c.r * 255.0f));
                line[4 * x + 1] = std::uint8_t(std::lround(c.g * 255.0f));
                line[4 * x + 2] = std::uint8_t(std::lround(c.b * 255.0f));
                line[4 * x + 3] = 255;
            }
        }
    paintLegend(image, settings.scale, settings.showNoise);
    if (!m_error.heat || m_error.heat->width() != rect.width || m_error.heat->height() != rect.height) {
        m_error.heat.reset();
        m_error.heat = Framebuffer::create(rect.width, rect.height, FramebufferFormat::RGBA16F, error);
        if (!m_error.heat)
            return false;
    }
    // Image rows are top first, GL's bottom first. The composite holds display-encoded values,
    // as the bytes are.
    const QImage flipped = image.mirrored();
    glBindTexture(GL_TEXTURE_2D, m_error.heat->colorTexture());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(
        GL_TEXTURE_2D, 0, 0, 0, rect.width, rect.height, GL_RGBA, GL_UNSIGNED_BYTE, flipped.constBits());
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_error.heat->framebufferId());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_composite->framebufferId());
    glBlitFramebuffer(0, 0, rect.width, rect.height, rect.x, rect.y, rect.x + rect.width,
        rect.y + rect.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    return true;
}

bool CompareRenderer::drawErrorView(const CompareCellDraw& reference, const CompareCellDraw& heat,
    double scale, bool heatShown, std::string* error)
{
    const ErrorCompare& settings = reference.project.compare.error;
    ErrorViewStats& stats = m_error.stats;
    stats.scale = settings.scale;
    stats.showingNoise = settings.showNoise;
    if (reference.assets.environment.isEmpty()) {
        // Its environment or lighting is on its way. What was summed stays (a new environment
        // changes the key; lighting for another split-sum quality does not).
        fill(reference.rect, kLoadingGrey);
        fill(heat.rect, kLoadingGrey);
        m_stats.cellsLoading += 2;
        touchMaps(reference);
        m_error.heatSamples = -1;
        return true;
    }
    const int width = reference.rect.width;
    const int height = reference.rect.height;
    // The real-time image depends on all of these; the reference on all but the split sum's
    // precompute quality.
    CellKey tested = keyOf(reference, 1.0);
    tested.project = withoutDisplaySettings(std::move(tested.project));
    CellKey accumulation = tested;
    accumulation.project.environment.quality = {};
    // While the user drags, each frame starts again (what is summed moves); the reference then
    // shows its split-sum frame, as the single view does.
    const bool restart = !m_error.accumulation || *m_error.accumulation != accumulation || scale < 1.0
        || m_error.test.width() != width || m_error.test.height() != height;
    // The real-time image is measured on still frames only: a drag's frames show the split sum in
    // both cells and the heat map waits (a full-size float render and read-back a frame would
    // slow the drag).
    const bool previewing = scale < 1.0;
    const bool retest = !previewing && (restart || !m_error.tested || *m_error.tested != tested);
    if (previewing)
        m_error.tested.reset();

    const std::optional<RenderScene> preview = sceneOf(reference, IblMethod::SplitSum, error);
    std::optional<RenderScene> sampled
        = preview ? sceneOf(reference, IblMethod::Reference, error) : std::nullopt;
    if (!sampled)
        return false;
    // Like for like: the real-time image shades each pixel at its centre (MSAA resolves only
    // edges, which the mask leaves out), so the reference does too. Jittered, it would be the
    // pixel's average, and a detailed normal map's aliasing would count as lighting error.
    sampled->pixelCentres = true;
    if (retest) {
        // The real-time image the error is of: the preview at the cell's full size, in float,
        // with the object's coverage in alpha for the mask.
        RenderScene covered = *preview;
        covered.coverageAlpha = true;
        const std::optional<Image> test = m_frames->renderImage(
            covered, width, height, FrameOutput::LinearRadiance, error, FramebufferFormat::RGBA32F);
        if (!test)
            return false;
        m_error.test = *test;
        m_error.mask = objectMask(m_error.test);
        m_error.heatSamples = -1;
        m_error.tested = tested;
    }
    if (restart) {
        m_error.reference = Image();
        m_error.accumulation = accumulation;
        stats = {};
        stats.scale = settings.scale;
        stats.showingNoise = settings.showNoise;
    }
    // refine() draws in pairs, one to each accumulator half: the noise is known after two draws.
    const int drawSamples = m_error.drawSamples;
    if (!m_frames->refine(*preview, *sampled, m_composite->framebufferId(), reference.rect, restart,
            drawSamples, error, kErrorSlot))
        return false;
    const FrameRenderer::Refinement& state = m_frames->refinement(kErrorSlot);
    if (!restart && state.draws > 0)
        m_error.drawSamples = ViewportRenderer::nextDrawSamples(
            state.lastDrawSamples, state.lastDrawMs, ViewportRenderer::kRefineDrawBudgetMs);
    stats.samples = state.samples;
    stats.target = state.target;
    stats.seconds = state.seconds;
    stats.complete = state.done();

    // The heat map is made of the accumulation the refinement read back for its last noise
    // estimate (after a pair of draws, at most every kNoiseIntervalSeconds or four draws, and at
    // the end): nothing reads the halves back twice, and a large cell is not re-measured on
    // every 100 ms draw.
    const std::optional<FrameAccumulator::Spread>& spread = m_frames->refinementSpread(kErrorSlot);
    if (!state.showing || !spread) {
        // A few samples are noise, not a measure: the heat map waits.
        fill(heat.rect, kLoadingGrey);
        return true;
    }
    const bool current = heatShown && m_error.heatSamples == spread->samples
        && m_error.heatScale == settings.scale && m_error.heatNoise == settings.showNoise;
    if (current)
        return true; // nothing new: the heat map in the composite stands
    if (m_error.heatSamples != spread->samples) {
        stats.noise = relativeNoiseRmse(spread->mean, spread->variance, m_error.mask);
        m_error.reference = spread->mean;
        m_error.variance = spread->variance;
        stats.error = errorStats(m_error.test, m_error.reference, m_error.mask);
    }
    const std::vector<float> values = settings.showNoise
        ? relativeNoise(m_error.reference, m_error.variance, m_error.mask)
        : relativeErrors(m_error.test, m_error.reference, m_error.mask);
    if (!drawHeatMap(heat, values, error))
        return false;
    m_error.heatSamples = spread->samples;
    m_error.heatScale = settings.scale;
    m_error.heatNoise = settings.showNoise;
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
    m_frames->precompute().setMemoryBudget(CacheBudget::bytes()); // the user's (ui/widgets/CacheBudget.h)
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
        m_accumulated.assign(cells.size(), std::nullopt);
        m_cellDrawSamples.assign(cells.size(), 1);
        m_frames->dropRefinements([](int slot) { return slot == kErrorSlot; });
        const float gap = displayGrey(kGapGrey);
        m_composite->clear(glm::vec4(gap, gap, gap, 1.0f));
        m_rects = std::move(rects);
    }
    const bool reduced = scale < 1.0;
    m_frames->textureCache().setMaxAnisotropy(TextureFiltering::anisotropyFor(m_glInfo, reduced));

    bool ok = true;
    std::set<std::pair<std::uint64_t, std::uint64_t>> shown;
    const auto findKind = [&cells](CompareCellDraw::Kind kind) {
        return std::find_if(
            cells.begin(), cells.end(), [kind](const CompareCellDraw& c) { return c.kind == kind; });
    };
    const auto referenceCell = findKind(CompareCellDraw::Kind::Reference);
    const auto heatCell = findKind(CompareCellDraw::Kind::Error);
    m_stats.error.reset();
    if (referenceCell != cells.end() && heatCell != cells.end()) {
        const std::size_t r = std::size_t(referenceCell - cells.begin());
        const std::size_t h = std::size_t(heatCell - cells.begin());
        if (!referenceCell->assets.environment.isEmpty())
            shown.insert(lightingKeyOf(*referenceCell));
        CellKey key = keyOf(*referenceCell, scale);
        const ErrorCompare& settings = referenceCell->project.compare.error;
        const bool kept = m_drawn[r] && *m_drawn[r] == key && m_drawn[h]
            && m_frames->refinement(kErrorSlot).done() && m_error.heatScale == settings.scale
            && m_error.heatNoise == settings.showNoise;
        std::string cellProblem;
        if (kept) {
            m_stats.cellsKept += 2;
            touchMaps(*referenceCell);
        } else if (drawErrorView(*referenceCell, *heatCell, scale, m_drawn[h].has_value(), &cellProblem)) {
            m_drawn[r] = std::move(key);
            m_drawn[h] = m_drawn[r];
            m_stats.cellsDrawn += 2;
        } else {
            fill(referenceCell->rect, kLoadingGrey);
            fill(heatCell->rect, kLoadingGrey);
            m_drawn[r].reset();
            m_drawn[h].reset();
            m_error.accumulation.reset();
            *error = "CompareRenderer::paint: " + cellProblem;
            ok = false;
        }
        m_stats.error = m_error.stats;
    }
    // Cells of a sampled method converge while the view is still, sharing one frame's budget of
    // drawing (each draw sized to its share, as the single view's are to the whole).
    const auto sampledCell = [reduced](const CompareCellDraw& cell) {
        return !reduced && cell.kind == CompareCellDraw::Kind::Shaded && !cell.assets.environment.isEmpty()
            && cell.project.environment.method != IblMethod::SplitSum;
    };
    const auto sampledCells = std::count_if(cells.begin(), cells.end(), sampledCell);
    const double cellBudgetMs
        = ViewportRenderer::kRefineDrawBudgetMs / double(std::max<std::ptrdiff_t>(sampledCells, 1));
    m_stats.cellsRefining = 0;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const CompareCellDraw& cell = cells[i];
        if (cell.kind != CompareCellDraw::Kind::Shaded)
            continue; // the error view's, drawn above
        if (!cell.assets.environment.isEmpty())
            shown.insert(lightingKeyOf(cell));
        CellKey key = keyOf(cell, scale);
        if (sampledCell(cell)) {
            // What the samples sum: the cell without its display settings (an exposure edit shows
            // the same samples anew).
            CellKey accumulation = keyOf(cell, 1.0);
            accumulation.project = withoutDisplaySettings(std::move(accumulation.project));
            const bool restart = !m_accumulated[i] || *m_accumulated[i] != accumulation;
            const bool done = !restart && m_frames->refinement(int(i)).done();
            if (done && m_drawn[i] && *m_drawn[i] == key) {
                ++m_stats.cellsKept;
                touchMaps(cell);
                continue;
            }
            std::string cellProblem;
            if (refineCell(cell, i, restart, cellBudgetMs, &cellProblem)) {
                m_drawn[i] = std::move(key);
                m_accumulated[i] = std::move(accumulation);
                ++m_stats.cellsDrawn;
                if (!m_frames->refinement(int(i)).done())
                    ++m_stats.cellsRefining;
            } else {
                fill(cell.rect, kLoadingGrey);
                m_drawn[i].reset();
                m_accumulated[i].reset();
                if (ok)
                    *error = "CompareRenderer::paint: " + cellProblem;
                ok = false;
            }
            continue;
        }
        m_accumulated[i].reset(); // drawn by the split sum: a later still frame starts again
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
