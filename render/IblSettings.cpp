#include "render/IblSettings.h"
#include "core/project/Project.h"
#include "core/support/Fnv1a.h"

#include <algorithm>
#include <bit>

namespace facet {

namespace {

// Bumped whenever a pass's algorithm changes, so that old disk-cache files stop matching.
// 2: roughness-to-level map r (2 - r); 3: the DFG key holds the visibility term (version 2's DFG
// entries were all height-correlated Smith whatever the material's V); 4: a map wider than 4x
// the cube is area-filtered to that width before the cube pass and SH9.
constexpr std::int32_t kAlgorithmVersion = 5;
// The DFG table's own version (its passes changed alone): 4: alpha holds fresnel_mix's diffuse
// weight W(n.v) (version 3's tables hold 1 there). Environment sets keep kAlgorithmVersion.
constexpr std::int32_t kDfgAlgorithmVersion = 4;

int mipChainLength(int size)
{
    return std::bit_width(unsigned(std::max(size, 1)));
}

} // namespace

std::uint64_t IblSettings::hash() const
{
    Fnv1a64 h;
    h.addUint32(std::uint32_t(kAlgorithmVersion));
    for (int v : {cubeSize, prefilterSize, prefilterMipLevels, prefilterSamples, irradianceSize,
             irradianceSamples, dfgSize, dfgSamples, int(irradiance)})
        h.addUint32(std::uint32_t(v));
    return h.value();
}

std::uint64_t IblSettings::dfgHash(Visibility visibility) const
{
    // The visibility by its name's bytes, not int(visibility): reordering the enum must not
    // make one variant's disk entries answer for another's.
    Fnv1a64 h;
    h.addUint32(std::uint32_t(kDfgAlgorithmVersion));
    h.addUint32(0x44464700); // "DFG": a different key space from hash()
    h.addUint32(std::uint32_t(dfgSize));
    h.addUint32(std::uint32_t(dfgSamples));
    for (const char* c = toString(visibility); *c; ++c)
        h.addUint32(static_cast<unsigned char>(*c));
    return h.value();
}

IblSettings IblSettings::sanitized() const
{
    IblSettings s = *this;
    s.cubeSize = std::clamp(s.cubeSize, 1, 4096);
    s.prefilterSize = std::clamp(s.prefilterSize, 1, 4096);
    s.prefilterMipLevels = std::clamp(s.prefilterMipLevels, 1, mipChainLength(s.prefilterSize));
    s.prefilterSamples = std::clamp(s.prefilterSamples, 1, 1 << 16);
    s.irradianceSize = std::clamp(s.irradianceSize, 1, 1024);
    s.irradianceSamples = std::clamp(s.irradianceSamples, 1, 1 << 16);
    s.dfgSize = std::clamp(s.dfgSize, 2, 1024);
    s.dfgSamples = std::clamp(s.dfgSamples, 1, 1 << 16);
    return s;
}

IblSettings IblSettings::forImage(int equirectWidth) const
{
    IblSettings s = sanitized();
    const unsigned wanted = std::bit_ceil(unsigned(std::max(equirectWidth / 2, 16)));
    s.cubeSize = std::min(s.cubeSize, int(std::min(wanted, 4096u)));
    s.prefilterSize = std::min(s.prefilterSize, s.cubeSize);
    s.prefilterMipLevels = std::clamp(s.prefilterMipLevels, 1, mipChainLength(s.prefilterSize));
    return s;
}

// Chosen from `facet bench` (docs/benchmarks.md, llvmpipe on 2 cores): the error against the
// ground truth stops falling at 128 prefilter samples (256 / 512 / 1024: same mean error, the
// pass 3x / 5x / 7x longer), and the irradiance map's error is the same with 384, 1536 or 6144
// source texels, so every preset sums 384 or 1536; SH9 stays an option, never a default (3.1%
// vs 12.1% relative RMSE, red dielectric r 1 under studio). cubeSize is a maximum (forImage).
IblSettings IblSettings::preset(IblQuality quality)
{
    IblSettings s;
    switch (quality) {
    case IblQuality::Default:
        return s; // the member initialisers above
    case IblQuality::Draft:
        s.cubeSize = 128;
        s.prefilterSize = 64;
        s.prefilterMipLevels = 5;
        s.prefilterSamples = 64;
        s.irradianceSize = 16;
        s.irradianceSamples = 384; // 8x8 source texels a face
        s.dfgSize = 32;
        s.dfgSamples = 256;
        return s;
    case IblQuality::High:
        s.cubeSize = 512;
        s.prefilterSize = 256;
        s.prefilterMipLevels = 7;
        s.prefilterSamples = 256;
        s.irradianceSize = 32;
        s.irradianceSamples = 1536; // 16x16 source texels a face
        s.dfgSize = 64;
        s.dfgSamples = 2048;
        return s;
    }
    return s;
}

std::optional<IblSettings> IblSettings::preset(const std::string& name)
{
    const std::optional<IblQuality> quality = iblQualityFromString(name);
    return quality ? std::optional(preset(*quality)) : std::nullopt;
}

std::vector<std::string> IblSettings::presetNames()
{
    std::vector<std::string> names;
    for (IblQuality quality : {IblQuality::Draft, IblQuality::Default, IblQuality::High})
        names.emplace_back(toString(quality));
    return names;
}

} // namespace facet
