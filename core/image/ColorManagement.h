#pragma once
// OpenColorIO display/view transforms for the tone-map pass. The config is the file named by the
// `OCIO` environment variable (what studio pipelines expect), else a built-in one made in code:
// OCIO 2.1 has no Config::CreateFromBuiltinConfig (2.2), but its built-in transform registry
// has the ACES output transforms and the display encodings (docs/architecture.md, "OpenColorIO 2.1").
//
// Facet's radiance is linear Rec.709 (docs/architecture.md); every processor here starts from it. CPU
// processors are the twins of render/OcioDisplayTransform (the same OCIO processor, run on the
// GPU). No GL here. OCIO throws; nothing here does: failures return empty values and a message
// "ColorManagement::<function>: ...".

#include <OpenColorIO/OpenColorIO.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace facet {

namespace OCIO = OCIO_NAMESPACE;

class ColorManagement {
public:
    // `source()` of the built-in config.
    static constexpr const char* kBuiltInSource = "<built-in config>";

    // The built-in config (docs/rendering.md, "Colour management"): scene reference ACES2065-1;
    // colour spaces "Linear Rec.709 (sRGB)" (role scene_linear), "ACEScg", "ACES2065-1",
    // "CIE-XYZ-D65" and "Raw" (data); displays "sRGB - Display" and "Rec.1886 Rec.709 - Display",
    // each with the views "ACES 1.0 - SDR Video", "Un-tone-mapped" and "Raw". Names as in
    // OCIO 2.2's built-in studio/cg configs, so projects carry over to a studio config.
    static ColorManagement builtIn();
    // Loads an OCIO config file. Failure: "ColorManagement::fromFile: cannot load OCIO config
    // '<path>': <OCIO's message>".
    static std::optional<ColorManagement> fromFile(const std::string& path, std::string* error);
    // fromFile($OCIO) when OCIO is set and not empty, else builtIn().
    static std::optional<ColorManagement> fromEnvironment(std::string* error);
    // The process-wide config render/ uses: fromEnvironment() on the first call, remembered (a
    // failure too, so a broken $OCIO is reported every time and not re-read every frame).
    static std::shared_ptr<const ColorManagement> shared(std::string* error);

    // The config file's path, or kBuiltInSource.
    const std::string& source() const { return m_source; }
    // Identifies the config's content (source + OCIO's cache id): the key render/ caches by.
    const std::string& identity() const { return m_identity; }
    const OCIO::ConstConfigRcPtr& config() const { return m_config; }
    // How Facet's linear Rec.709 enters the config, for messages and docs: a colour space name,
    // or a description of the conversion into the config's aces_interchange role.
    const std::string& workingSpaceDescription() const { return m_workingSpaceDescription; }

    // Active displays, in the config's order.
    std::vector<std::string> displays() const;
    // Active views of `display`; nullopt with "ColorManagement::views: ..." (listing the displays)
    // for an unknown display.
    std::optional<std::vector<std::string>> views(const std::string& display, std::string* error) const;
    // Whether the config has `display` and, under it, `view`. False with *problem naming the field
    // ("ocioDisplay: unknown display \"X\" in <config> (available: ...)", or "ocioView: ...").
    bool checkDisplayView(const std::string& display, const std::string& view, std::string* problem) const;
    std::string defaultDisplay() const;
    std::string defaultView(const std::string& display) const;

    // Linear Rec.709 -> (display, view). An unknown display or view yields nullptr and a message
    // that lists what is available.
    OCIO::ConstProcessorRcPtr displayProcessor(
        const std::string& display, const std::string& view, std::string* error) const;
    // The CPU twin of the GPU pass (without the exposure, which Facet applies before).
    OCIO::ConstCPUProcessorRcPtr cpuProcessor(
        const std::string& display, const std::string& view, std::string* error) const;

private:
    ColorManagement(OCIO::ConstConfigRcPtr config, std::string source);
    // Decides how linear Rec.709 enters the config (m_workingColorSpace, m_toWorkingSpace):
    // false when the config offers no way.
    bool findWorkingSpace();

    OCIO::ConstConfigRcPtr m_config;
    std::string m_source;
    std::string m_identity;
    // The colour space the display/view transform starts from, and the transform (may be null)
    // that takes linear Rec.709 into it.
    std::string m_workingColorSpace;
    OCIO::ConstTransformRcPtr m_toWorkingSpace;
    std::string m_workingSpaceDescription;
};

} // namespace facet
