#pragma once
// The GPU side of the Compare view (not a widget): every cell of a compare mode drawn through ONE
// render::FrameRenderer in the view's GL context, so an environment shown by several cells is
// looked up once (its IBL set is shared; FrameRenderer's IblPrecompute caches by content) and
// targets of one cell size are pooled.
//
// Cells are drawn into a retained composite target of the view's size, and only the cells whose
// inputs changed since they were last drawn (their project variant, the environment and map
// images, their rectangle, the resolution scale) are drawn again; the composite is then copied to
// the widget. A linked orbit redraws every linked cell; an unlinked cell's orbit redraws that cell.
// A cell may be clipped to a part of its rectangle (A/B's split): it is rendered whole into a
// scratch target and only the clipped part is copied, so A and B of one split are rendered at the
// same size and camera and line up pixel for pixel.
//
// Every call needs the view's context current; destroy it with the context current.

#include "core/image/ImageMetrics.h"
#include "core/project/Project.h"
#include "core/project/ProjectAssets.h"
#include "render/FrameRenderer.h"
#include "render/GLInfo.h"
#include "render/IblPrecompute.h"

#include <QString>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace facet {

// One cell of a frame.
struct CompareCellDraw {
    // What the cell shows: its project shaded as the window previews (the split sum), or a part of
    // the error view (core/project/CompareLayout.h ErrorCompare): the reference converging over frames,
    // or the heat map of the real-time image's error against it. An error view is one Reference
    // cell and one Error cell (and a Shaded cell of the real-time image) of one size.
    enum class Kind { Shaded, Reference, Error };
    Kind kind = Kind::Shaded;
    Project project; // what the cell shows (core/project/CompareLayout.h's variant of the document's project)
    // The mesh, the map images of project's materials and the environment (rotation and
    // intensity applied); an empty environment: still loading, the cell is filled with kLoadingGrey.
    ProjectAssets assets;
    FrameRect rect; // device pixels, origin bottom-left (GL's)
    std::optional<FrameRect> clip; // only this part of rect is written (within rect)
};

// The error view's state after a frame (CompareFrameStats::error).
struct ErrorViewStats {
    int samples = 0; // the reference's samples per pixel so far
    int target = 0; // ErrorCompare::samples (1 for a debug view the samples do not change)
    double seconds = 0.0; // of the reference's draws
    // At its samples, or its noise estimate at most FrameRenderer::kRefinementNoiseTarget.
    bool complete = false;
    bool done() const { return complete; }
    // The numbers of the heat map shown (core/image/ImageMetrics errorStats of the real-time image
    // against the reference's mean over objectMask of the real-time image's coverage); unset
    // until the reference is shown (FrameRenderer::kRefinementShownAfter samples).
    std::optional<ImageErrorStats> error;
    // The reference's own noise estimate over the same pixels (relativeNoiseRmse); unset until
    // both accumulator halves hold a draw.
    std::optional<double> noise;
    bool showingNoise = false; // the heat map shows the noise, not the error
    double scale = 0.0; // the heat map's top
};

struct CompareFrameStats {
    std::uint64_t frameNumber = 0; // frames drawn since the renderer was made
    int cellsDrawn = 0; // cells rendered in the last frame (the rest were kept)
    int cellsKept = 0;
    int cellsLoading = 0; // filled with kLoadingGrey: their environment is still loading
    bool reduced = false;
    double frameMs = 0.0; // render + tone map + composite, GPU finished (glFinish), without IBL
    double iblMs = 0.0; // IBL lookups and precomputes this frame ran
    // Since the renderer was made: environments whose IBL set this renderer asked for (one per
    // environment image and quality, however many cells show it), and how many of those ran the
    // precompute passes or came from the disk cache.
    int iblRequests = 0;
    // Since the renderer was made: material textures the cells uploaded (0 for maps the single
    // view already put on the GPU: the views share their textures, ui/viewport/ViewShareGroup).
    int texturesUploaded = 0;
    int texturesResident = 0; // material textures on the GPU after the last frame (the shared cache)
    int iblComputed = 0;
    int iblFromDisk = 0;
    // Of those, the sets the Compare view's lighting worker made off the GUI thread (adopted).
    int iblFromWorker = 0;
    // Set while an error view is shown.
    std::optional<ErrorViewStats> error;
    // Shaded cells whose project's IBL method is a sampled one (fis, reference) converge over
    // frames as the single view's still frame does (FrameRenderer::refine): how many are still
    // adding samples after the last frame.
    int cellsRefining = 0;
};

class CompareRenderer {
public:
    // Gap between cells (and the free part of a grid whose last row is short) and the loading
    // fill, as linear values. The composite holds display-encoded pixels (FrameRenderer's output)
    // and is shown as is, so they are written sRGB-encoded (displayGrey): 0.06 shows as 69 of 255,
    // 0.18 as 118; written raw they showed as 15 and 46, a black hole where a grid has no cell.
    static constexpr float kGapGrey = 0.06f;
    static constexpr float kLoadingGrey = 0.18f;
    // The sRGB encoding of linear grey `linear` (core/image/ToneMap.h tonemap::linearToSrgb): what a fill
    // writes.
    static float displayGrey(float linear);

    // Needs the context current. `cacheDirectory` empty: the IBL disk cache's default folder.
    explicit CompareRenderer(const QString& cacheDirectory = {}, bool useDiskCache = true);
    // Draws with the IBL results and material textures of the window's other views
    // (ui/viewport/ViewShareGroup), in a context sharing with theirs.
    CompareRenderer(std::shared_ptr<IblPrecompute> precompute, std::shared_ptr<TextureCache> textures);
    ~CompareRenderer();
    CompareRenderer(const CompareRenderer&) = delete;
    CompareRenderer& operator=(const CompareRenderer&) = delete;

    // Draws `cells` at `scale` in (0, 1] into `targetFramebuffer` (width x height device pixels):
    // the cells whose inputs changed, then the whole composite. False with *error
    // ("CompareRenderer::paint: ...") when a cell could not be drawn (it is left grey; the others
    // are drawn).
    bool paint(const std::vector<CompareCellDraw>& cells, unsigned targetFramebuffer, int width, int height,
        double scale, std::string* error);
    // Forgets what was drawn: the next paint draws every cell.
    void invalidate();
    // Whether the material texture of `path` (that file version, that colour space) is complete
    // on the GPU: a decoded copy the single view released (a stand-in) can then be drawn as is.
    bool textureReady(const std::string& path, std::int64_t timestamp, ColorEncoding colorSpace) const;

    // Whether drawing `cell` would prepare lighting (look up or precompute an IBL set) this
    // renderer does not hold yet: its environment has loaded and no cell drawn since showed it
    // at its IBL quality. lightingToPrepare: how many distinct sets `cells` need so (one per
    // environment image and quality, however many cells show it).
    bool needsLighting(const CompareCellDraw& cell) const;
    int lightingToPrepare(const std::vector<CompareCellDraw>& cells) const;
    // The IBL settings a cell is lit with (its project's quality).
    static IblSettings lightingSettingsOf(const CompareCellDraw& cell);
    // A set made off this thread (the Compare view's lighting worker) for IblPrecompute key
    // `key`: put into the shared precompute's memory, where the cells' next frame finds it, and
    // counted (iblComputed or iblFromDisk) as `stats` say.
    void adoptLighting(std::uint64_t key, std::shared_ptr<const IblTextures> textures, const IblStats& stats);

    const CompareFrameStats& lastFrame() const { return m_stats; }
    // Whether the error view or a cell shown is converging: paint again to add samples.
    bool isRefining() const;
    // The refinement of Shaded cell `index` of the last paint: null when the cell is drawn by the
    // split sum (its project's method, or a reduced frame while the user drags).
    const FrameRenderer::Refinement* cellRefinement(std::size_t index) const;
    // The images the error view's numbers come from (tests compare them with core/image/ImageMetrics):
    // the real-time image (linear, alpha the coverage), the reference's mean, the mask. Empty
    // before the first error frame.
    const Image& errorTestImage() const { return m_error.test; }
    const Image& errorReferenceImage() const { return m_error.reference; }
    const PixelMask& errorMask() const { return m_error.mask; }
    const std::vector<float>& errorVariance() const { return m_error.variance; }
    FrameRenderer& frames() { return *m_frames; }

private:
    // What a cell was drawn from: equal keys, equal pixels.
    struct CellKey {
        Project project;
        std::uint64_t environmentHash = 0; // Environment::contentHash(), 0 for none
        double environmentRotation = 0.0;
        double environmentIntensity = 1.0;
        std::vector<const void*> maps;
        const void* mesh = nullptr;
        int rect[4] {};
        int clip[4] {};
        double scale = 1.0;
        bool operator==(const CellKey&) const = default;
    };
    static CellKey keyOf(const CompareCellDraw& cell, double scale);
    static std::pair<std::uint64_t, std::uint64_t> lightingKeyOf(const CompareCellDraw& cell);
    bool drawCell(const CompareCellDraw& cell, double scale, std::string* error);
    // One step of a Shaded cell's refinement by its project's sampled method (slot `index` of
    // FrameRenderer::refine); `drawBudgetMs`: its share of a frame's drawing.
    bool refineCell(const CompareCellDraw& cell, std::size_t index, bool restart, double drawBudgetMs,
        std::string* error);
    // The scratch target a clipped cell is rendered into whole, at the cell's size.
    Framebuffer* scratchFor(const CompareCellDraw& cell, std::string* error);
    // The clipped part of the scratch target into the composite.
    void copyClip(const CompareCellDraw& cell);
    // The error view's Reference and Error cells (drawn every frame until the reference is done).
    // `heatShown`: the composite holds the heat map last made (it need not be drawn again when
    // nothing it shows changed).
    bool drawErrorView(const CompareCellDraw& reference, const CompareCellDraw& heat, double scale,
        bool heatShown, std::string* error);
    bool drawHeatMap(const CompareCellDraw& heat, const std::vector<float>& values, std::string* error);
    std::optional<RenderScene> sceneOf(
        const CompareCellDraw& cell, std::optional<IblMethod> method, std::string* error);
    std::shared_ptr<const IblTextures> lightingFor(const CompareCellDraw& cell, std::string* error);
    // iblComputed / iblFromDisk for one set's preparation.
    void countLighting(const IblStats& stats);
    void fill(const FrameRect& rect, float grey);
    // Marks the cell's map textures used this frame without drawing it (a kept or waiting cell).
    void touchMaps(const CompareCellDraw& cell);

    std::unique_ptr<FrameRenderer> m_frames;
    std::optional<Framebuffer> m_composite;
    std::optional<Framebuffer> m_scratch;
    std::vector<std::optional<CellKey>> m_drawn; // by cell index
    // What each refining cell's samples sum (its key without display settings), and its draws'
    // size; unset for a cell drawn by the split sum.
    std::vector<std::optional<CellKey>> m_accumulated;
    std::vector<int> m_cellDrawSamples;
    std::vector<FrameRect> m_rects; // the cells' rectangles in the last paint
    // The IBL sets of the environments shown, by pixel identity and IBL quality.
    std::map<std::pair<std::uint64_t, std::uint64_t>, std::shared_ptr<const IblTextures>> m_lighting;
    CompareFrameStats m_stats;
    GLInfo m_glInfo;
    // The error view between frames.
    struct ErrorPane {
        std::optional<CellKey> accumulation; // what the reference accumulates (no display settings)
        std::optional<CellKey> tested; // what the real-time image shows (the same and its IBL quality)
        std::optional<CellKey> shown; // what the reference cell shows (with them)
        Image test; // the real-time image, linear, alpha the coverage
        PixelMask mask;
        Image reference; // the reference's mean when the heat map was made
        std::vector<float> variance; // its variance per pixel (FrameAccumulator::Spread)
        std::optional<Framebuffer> heat; // the heat map's upload target
        int heatSamples = -1; // the samples, scale and mode the heat map was made with
        double heatScale = 0.0;
        bool heatNoise = false;
        int drawSamples = 1;
        ErrorViewStats stats;
    } m_error;
};

} // namespace facet
