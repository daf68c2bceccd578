#include "core/image/ColorManagement.h"

#include <QtGlobal>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <exception>
#include <mutex>

#include "core/support/Failure.h"
#include "core/support/FileCheck.h"

namespace facet {

namespace {

// "\"a\", \"b\"" for messages; "(none)" for an empty list.
std::string quotedList(const std::vector<std::string>& names)
{
    if (names.empty())
        return "(none)";
    std::string out;
    for (const std::string& name : names)
        out += (out.empty() ? "\"" : ", \"") + name + "\"";
    return out;
}

OCIO::BuiltinTransformRcPtr builtin(
    const char* style, OCIO::TransformDirection direction = OCIO::TRANSFORM_DIR_FORWARD)
{
    OCIO::BuiltinTransformRcPtr transform = OCIO::BuiltinTransform::Create();
    transform->setStyle(style);
    transform->setDirection(direction);
    return transform;
}

// Linear Rec.709 (sRGB primaries, D65) -> ACES2065-1 (AP0, D60), from the registry's
// building blocks: the inverse of "ACES-AP1 to linear Rec.709" (Bradford-adapted, as OCIO 2.2's
// cg-config defines its "Linear Rec.709 (sRGB)"), then ACEScg -> ACES2065-1.
OCIO::TransformRcPtr linearRec709ToAces2065()
{
    OCIO::GroupTransformRcPtr group = OCIO::GroupTransform::Create();
    group->appendTransform(builtin("UTILITY - ACES-AP1_to_LINEAR-REC709_BFD", OCIO::TRANSFORM_DIR_INVERSE));
    group->appendTransform(builtin("ACEScg_to_ACES2065-1"));
    return group;
}

OCIO::ColorSpaceRcPtr colorSpace(OCIO::ReferenceSpaceType reference, const char* name, const char* family,
    const char* description, OCIO::TransformRcPtr transform, OCIO::ColorSpaceDirection direction)
{
    OCIO::ColorSpaceRcPtr space = OCIO::ColorSpace::Create(reference);
    space->setName(name);
    space->setFamily(family);
    space->setDescription(description);
    if (transform)
        space->setTransform(transform, direction);
    return space;
}

OCIO::ViewTransformRcPtr viewTransform(
    const char* name, const char* description, OCIO::TransformRcPtr transform)
{
    OCIO::ViewTransformRcPtr view = OCIO::ViewTransform::Create(OCIO::REFERENCE_SPACE_SCENE);
    view->setName(name);
    view->setDescription(description);
    view->setTransform(transform, OCIO::VIEWTRANSFORM_DIR_FROM_REFERENCE);
    return view;
}

// Names under which configs in common use hold linear Rec.709: OCIO 2.2's studio/cg configs
// (and their alias lin_rec709), Blender's, the ACES 1.x OCIO v1 configs.
constexpr const char* kLinearRec709Names[] = {"Linear Rec.709 (sRGB)", "lin_rec709", "lin_srgb",
    "Linear Rec.709", "Utility - Linear - sRGB", "Linear sRGB", "Linear"};

} // namespace

ColorManagement::ColorManagement(OCIO::ConstConfigRcPtr config, std::string source)
    : m_config(std::move(config))
    , m_source(std::move(source))
{
    m_identity = m_source + "|" + m_config->getCacheID();
}

ColorManagement ColorManagement::builtIn()
{
    // Built once per process: the config is immutable and OCIO caches processors per config.
    static const OCIO::ConstConfigRcPtr config = []() -> OCIO::ConstConfigRcPtr {
        try {
            OCIO::ConfigRcPtr c = OCIO::Config::CreateRaw()->createEditableCopy();
            c->clearDisplays();
            c->clearColorSpaces();
            c->setName("facet-builtin");
            c->setDescription(
                "Facet's built-in OCIO config (core/image/ColorManagement.cpp): scene reference "
                "ACES2065-1, display reference CIE-XYZ-D65, ACES 1.0 SDR video output.");
            const auto toReference = OCIO::COLORSPACE_DIR_TO_REFERENCE;
            const auto fromReference = OCIO::COLORSPACE_DIR_FROM_REFERENCE;
            // Scene-referred spaces (reference: ACES2065-1).
            c->addColorSpace(colorSpace(OCIO::REFERENCE_SPACE_SCENE, "ACES2065-1", "ACES",
                "ACES2065-1 (AP0 primaries, D60), the scene reference", nullptr, toReference));
            c->addColorSpace(colorSpace(OCIO::REFERENCE_SPACE_SCENE, "ACEScg", "ACES",
                "ACEScg (AP1 primaries, linear)", builtin("ACEScg_to_ACES2065-1"), toReference));
            c->addColorSpace(colorSpace(OCIO::REFERENCE_SPACE_SCENE, "Linear Rec.709 (sRGB)", "Utility",
                "Linear Rec.709 primaries, D65: Facet's working space", linearRec709ToAces2065(),
                toReference));
            OCIO::ColorSpaceRcPtr raw = colorSpace(
                OCIO::REFERENCE_SPACE_SCENE, "Raw", "Utility", "Data: no conversion", nullptr, toReference);
            raw->setIsData(true);
            c->addColorSpace(raw);
            // Display-referred spaces (reference: CIE XYZ, D65), the registry's display encodings.
            c->addColorSpace(colorSpace(OCIO::REFERENCE_SPACE_DISPLAY, "CIE-XYZ-D65", "Display",
                "CIE XYZ, D65 white, the display reference", nullptr, fromReference));
            c->addColorSpace(colorSpace(OCIO::REFERENCE_SPACE_DISPLAY, "sRGB - Display", "Display",
                "sRGB primaries, piecewise sRGB curve (IEC 61966-2-1)",
                builtin("DISPLAY - CIE-XYZ-D65_to_sRGB"), fromReference));
            c->addColorSpace(colorSpace(OCIO::REFERENCE_SPACE_DISPLAY, "Rec.1886 Rec.709 - Display",
                "Display", "Rec.709 primaries, Rec.1886 (gamma 2.4) curve",
                builtin("DISPLAY - CIE-XYZ-D65_to_REC.1886-REC.709"), fromReference));
            // View transforms: scene reference -> display reference.
            c->addViewTransform(
                viewTransform("ACES 1.0 - SDR Video", "ACES 1.0 RRT + SDR video ODT (100 nits, dim surround)",
                    builtin("ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - SDR-VIDEO_1.0")));
            c->addViewTransform(viewTransform("Un-tone-mapped",
                "Colorimetric: scene values shown as display values (not clipped)",
                builtin("UTILITY - ACES-AP0_to_CIE-XYZ-D65_BFD")));
            c->setDefaultViewTransformName("Un-tone-mapped");
            for (const char* display : {"sRGB - Display", "Rec.1886 Rec.709 - Display"}) {
                c->addDisplayView(
                    display, "ACES 1.0 - SDR Video", "ACES 1.0 - SDR Video", display, "", "", "");
                c->addDisplayView(display, "Un-tone-mapped", "Un-tone-mapped", display, "", "", "");
                c->addDisplayView(display, "Raw", "Raw", "");
            }
            c->setActiveDisplays("");
            c->setActiveViews("");
            c->setRole(OCIO::ROLE_SCENE_LINEAR, "Linear Rec.709 (sRGB)");
            c->setRole(OCIO::ROLE_DEFAULT, "Linear Rec.709 (sRGB)");
            c->setRole(OCIO::ROLE_DATA, "Raw");
            c->setRole(OCIO::ROLE_INTERCHANGE_SCENE, "ACES2065-1");
            c->setRole(OCIO::ROLE_INTERCHANGE_DISPLAY, "CIE-XYZ-D65");
            c->setRole("color_timing", "ACEScg");
            c->setRole("compositing_linear", "ACEScg");
            c->setRole("rendering", "ACEScg");
            c->validate();
            return c;
        } catch (const OCIO::Exception& e) {
            // The config is code: a failure is a programming error, which ColorManagementTest catches.
            // Fall back to OCIO's raw config (display "sRGB", view "Raw") so that nothing crashes.
            qCritical("ColorManagement::builtIn: the built-in OCIO config is invalid: %s", e.what());
            Q_ASSERT_X(false, "ColorManagement::builtIn", e.what());
            return OCIO::Config::CreateRaw();
        }
    }();
    ColorManagement result(config, kBuiltInSource);
    result.findWorkingSpace();
    return result;
}

std::optional<ColorManagement> ColorManagement::fromFile(const std::string& path, std::string* error)
{
    const std::string prefix = "ColorManagement::fromFile: cannot load OCIO config '" + path + "': ";
    // The check every input goes through (core/support/FileCheck.h): $OCIO naming a FIFO blocked `facet
    // render` and the window's start forever inside OCIO's open (issue 29).
    if (const FileCheck check = checkRegularFile(path); !check.ok()) {
        fail(prefix + check.problem, error);
        return std::nullopt;
    }
    try {
        OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(path.c_str());
        config->validate();
        ColorManagement result(config, path);
        if (!result.findWorkingSpace()) {
            fail(prefix
                    + "it has no linear Rec.709 colour space (e.g. \"Linear Rec.709 (sRGB)\"), no "
                      "aces_interchange role and no scene_linear role",
                error);
            return std::nullopt;
        }
        return result;
    } catch (const OCIO::Exception& e) {
        fail(prefix + e.what(), error);
    } catch (const std::exception& e) {
        fail(prefix + e.what(), error);
    }
    return std::nullopt;
}

std::optional<ColorManagement> ColorManagement::fromEnvironment(std::string* error)
{
    const char* path = std::getenv("OCIO");
    if (!path || !*path)
        return builtIn();
    std::string message;
    std::optional<ColorManagement> result = fromFile(path, &message);
    if (!result)
        fail(message + " (from the OCIO environment variable)", error);
    return result;
}

std::shared_ptr<const ColorManagement> ColorManagement::shared(std::string* error)
{
    static std::mutex mutex;
    static bool loaded = false;
    static std::shared_ptr<const ColorManagement> instance;
    static std::string loadError;
    const std::lock_guard<std::mutex> lock(mutex);
    if (!loaded) {
        loaded = true;
        std::optional<ColorManagement> result = fromEnvironment(&loadError);
        if (result)
            instance = std::make_shared<const ColorManagement>(std::move(*result));
    }
    if (!instance)
        fail(loadError, error);
    return instance;
}

bool ColorManagement::findWorkingSpace()
{
    // 1. A colour space that is linear Rec.709 by name (getColorSpace also resolves aliases).
    for (const char* name : kLinearRec709Names) {
        if (OCIO::ConstColorSpaceRcPtr space = m_config->getColorSpace(name)) {
            if (space->isData())
                continue;
            m_workingColorSpace = space->getName();
            m_toWorkingSpace = nullptr;
            m_workingSpaceDescription = "colour space \"" + m_workingColorSpace + "\"";
            return true;
        }
    }
    // 2. ACES-based configs (every OCIO v2 ACES config has the role): convert into ACES2065-1.
    if (m_config->hasRole(OCIO::ROLE_INTERCHANGE_SCENE)) {
        if (OCIO::ConstColorSpaceRcPtr space = m_config->getColorSpace(OCIO::ROLE_INTERCHANGE_SCENE)) {
            m_workingColorSpace = space->getName();
            m_toWorkingSpace = linearRec709ToAces2065();
            m_workingSpaceDescription
                = "linear Rec.709 converted to the aces_interchange role (\"" + m_workingColorSpace + "\")";
            return true;
        }
    }
    // 3. Last resort: the scene_linear role, whose primaries are then assumed to be Rec.709.
    if (m_config->hasRole(OCIO::ROLE_SCENE_LINEAR)) {
        if (OCIO::ConstColorSpaceRcPtr space = m_config->getColorSpace(OCIO::ROLE_SCENE_LINEAR)) {
            m_workingColorSpace = space->getName();
            m_toWorkingSpace = nullptr;
            m_workingSpaceDescription = "the scene_linear role (\"" + m_workingColorSpace
                + "\"), assumed to have Rec.709 primaries";
            return true;
        }
    }
    return false;
}

std::vector<std::string> ColorManagement::displays() const
{
    std::vector<std::string> names;
    try {
        const int count = m_config->getNumDisplays();
        for (int i = 0; i < count; ++i)
            names.emplace_back(m_config->getDisplay(i));
    } catch (const OCIO::Exception&) {
        // A config that loaded and validated lists its displays; nothing to report otherwise.
    }
    return names;
}

std::optional<std::vector<std::string>> ColorManagement::views(
    const std::string& display, std::string* error) const
{
    const std::vector<std::string> all = displays();
    if (std::find(all.begin(), all.end(), display) == all.end()) {
        fail("ColorManagement::views: unknown display \"" + display + "\" in " + m_source
                + " (available: " + quotedList(all) + ")",
            error);
        return std::nullopt;
    }
    std::vector<std::string> names;
    try {
        const int count = m_config->getNumViews(display.c_str());
        for (int i = 0; i < count; ++i)
            names.emplace_back(m_config->getView(display.c_str(), i));
    } catch (const OCIO::Exception& e) {
        fail("ColorManagement::views: " + std::string(e.what()), error);
        return std::nullopt;
    }
    return names;
}

bool ColorManagement::checkDisplayView(
    const std::string& display, const std::string& view, std::string* problem) const
{
    const std::vector<std::string> all = displays();
    if (std::find(all.begin(), all.end(), display) == all.end())
        return fail("ocioDisplay: unknown display \"" + display + "\" in " + m_source
                + " (available: " + quotedList(all) + ")",
            problem);
    std::string message;
    const std::optional<std::vector<std::string>> names = views(display, &message);
    if (!names)
        return fail("ocioView: " + message, problem);
    if (std::find(names->begin(), names->end(), view) == names->end())
        return fail("ocioView: display \"" + display + "\" of " + m_source + " has no view \"" + view
                + "\" (available: " + quotedList(*names) + ")",
            problem);
    return true;
}

std::string ColorManagement::defaultDisplay() const
{
    try {
        return m_config->getDefaultDisplay();
    } catch (const OCIO::Exception&) {
        return {};
    }
}

std::string ColorManagement::defaultView(const std::string& display) const
{
    try {
        return m_config->getDefaultView(display.c_str());
    } catch (const OCIO::Exception&) {
        return {};
    }
}

OCIO::ConstProcessorRcPtr ColorManagement::displayProcessor(
    const std::string& display, const std::string& view, std::string* error) const
{
    const std::string prefix = "ColorManagement::displayProcessor: ";
    std::string message;
    const std::optional<std::vector<std::string>> available = views(display, &message);
    if (!available) {
        // views() named itself; keep its explanation under this function's name.
        fail(prefix + message.substr(message.find(": ") + 2), error);
        return nullptr;
    }
    if (std::find(available->begin(), available->end(), view) == available->end()) {
        fail(prefix + "display \"" + display + "\" of " + m_source + " has no view \"" + view
                + "\" (available: " + quotedList(*available) + ")",
            error);
        return nullptr;
    }
    try {
        OCIO::DisplayViewTransformRcPtr displayView = OCIO::DisplayViewTransform::Create();
        displayView->setSrc(m_workingColorSpace.c_str());
        displayView->setDisplay(display.c_str());
        displayView->setView(view.c_str());
        if (!m_toWorkingSpace)
            return m_config->getProcessor(displayView);
        OCIO::GroupTransformRcPtr group = OCIO::GroupTransform::Create();
        group->appendTransform(m_toWorkingSpace->createEditableCopy());
        group->appendTransform(displayView);
        return m_config->getProcessor(group);
    } catch (const OCIO::Exception& e) {
        fail(prefix + "\"" + display + "\" / \"" + view + "\" in " + m_source + ": " + e.what(), error);
    }
    return nullptr;
}

OCIO::ConstCPUProcessorRcPtr ColorManagement::cpuProcessor(
    const std::string& display, const std::string& view, std::string* error) const
{
    std::string message;
    OCIO::ConstProcessorRcPtr processor = displayProcessor(display, view, &message);
    if (!processor) {
        fail("ColorManagement::cpuProcessor: " + message.substr(message.find(": ") + 2), error);
        return nullptr;
    }
    try {
        return processor->getDefaultCPUProcessor();
    } catch (const OCIO::Exception& e) {
        fail("ColorManagement::cpuProcessor: " + std::string(e.what()), error);
    }
    return nullptr;
}

} // namespace facet
