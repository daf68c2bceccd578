#include "core/shading/ThinFilm.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/mat3x3.hpp>

#include "core/shading/Brdf.h"

namespace facet::shading {

namespace {

// Linear Rec.709 from CIE XYZ (the extension's matrix; columns are X, Y, Z).
const glm::dmat3 kXyzToRec709(
    3.2404542, -0.9692660, 0.0556434, -1.5371385, 1.8760108, -0.2040259, -0.4985314, 0.0415560, 1.0572252);

double schlick(double f0, double cosTheta)
{
    const double m = std::clamp(1.0 - cosTheta, 0.0, 1.0);
    const double m2 = m * m;
    return f0 + (1.0 - f0) * m2 * m2 * m;
}

double smoothstep(double edge0, double edge1, double x)
{
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// The film's terms at one angle, per channel where the base's index differs: everything the
// series needs but the wavelength.
struct FilmTerms {
    bool totalReflection = false; // cos^2(theta2) < 0: the film reflects everything
    double R12 = 0.0;
    double T121 = 1.0;
    double opd = 0.0; // nanometres
    glm::dvec3 Rs {0.0}; // T121^2 R23 / (1 - R123)
    glm::dvec3 r123 {0.0};
    glm::dvec3 phi {0.0};
};

FilmTerms filmTerms(const ThinFilm& film, const glm::dvec3& baseF0, double cosTheta)
{
    FilmTerms terms;
    const double d = std::max(film.thickness, 0.0);
    const double eta2 = glm::mix(1.0, std::max(film.ior, 1.0), smoothstep(0.0, kThinFilmFadeThickness, d));
    const double cos1 = std::clamp(cosTheta, 0.0, 1.0);
    const double sin2Theta2 = (1.0 - cos1 * cos1) / (eta2 * eta2);
    const double cos2Theta2 = 1.0 - sin2Theta2;
    if (cos2Theta2 < 0.0) {
        terms.totalReflection = true;
        return terms;
    }
    const double cos2 = std::sqrt(cos2Theta2);
    const double r0 = (eta2 - 1.0) / (eta2 + 1.0);
    terms.R12 = schlick(r0 * r0, cos1);
    terms.T121 = 1.0 - terms.R12;
    const double phi12 = eta2 < 1.0 ? kPi : 0.0;
    const double phi21 = kPi - phi12;
    terms.opd = 2.0 * eta2 * d * cos2;
    for (int c = 0; c < 3; ++c) {
        const double sqrtF0 = std::sqrt(std::clamp(baseF0[c], 0.0, 0.9999));
        const double eta3 = (1.0 + sqrtF0) / (1.0 - sqrtF0);
        const double r1 = (eta3 - eta2) / (eta3 + eta2);
        const double R23 = schlick(r1 * r1, cos2);
        const double phi23 = eta3 < eta2 - kThinFilmIndexTolerance ? kPi : 0.0;
        const double R123 = std::clamp(terms.R12 * R23, 1e-5, 0.9999);
        terms.r123[c] = std::sqrt(R123);
        terms.Rs[c] = terms.T121 * terms.T121 * R23 / (1.0 - R123);
        terms.phi[c] = phi21 + phi23;
    }
    return terms;
}

// The extension's fitted sensitivity: the colour matching functions' Fourier transform at the
// optical path difference `opd` (nm), each XYZ row shifted by the phase of `shift`'s component
// (as the extension writes it), in linear Rec.709.
glm::dvec3 evalSensitivity(double opd, const glm::dvec3& shift)
{
    const double phase = 2.0 * kPi * opd * 1e-9;
    const glm::dvec3 val(5.4856e-13, 4.4201e-13, 5.2481e-13);
    const glm::dvec3 pos(1.6810e+06, 1.7953e+06, 2.2084e+06);
    const glm::dvec3 var(4.3278e+09, 9.3046e+09, 6.6121e+09);
    glm::dvec3 xyz;
    for (int i = 0; i < 3; ++i)
        xyz[i] = val[i] * std::sqrt(2.0 * kPi * var[i]) * std::cos(pos[i] * phase + shift[i])
            * std::exp(-phase * phase * var[i]);
    xyz.x += 9.7470e-14 * std::sqrt(2.0 * kPi * 4.5282e+09) * std::cos(2.2399e+06 * phase + shift[0])
        * std::exp(-4.5282e+09 * phase * phase);
    return kXyzToRec709 * (xyz / 1.0685e-7);
}

// One lobe of Wyman, Sloan and Shirley's fit: a Gaussian of different widths either side of mu.
double lobe(double lambda, double mu, double sigmaBelow, double sigmaAbove)
{
    const double t = (lambda - mu) / (lambda < mu ? sigmaBelow : sigmaAbove);
    return std::exp(-0.5 * t * t);
}

} // namespace

// [Wyman, Sloan and Shirley 2013, "Simple Analytic Approximations to the CIE XYZ Color Matching
// Functions", the multi-lobe fit].
glm::dvec3 colourMatchingFunctions(double lambda)
{
    return {1.056 * lobe(lambda, 599.8, 37.9, 31.0) + 0.362 * lobe(lambda, 442.0, 16.0, 26.7)
            - 0.065 * lobe(lambda, 501.1, 20.4, 26.2),
        0.821 * lobe(lambda, 568.8, 46.9, 40.5) + 0.286 * lobe(lambda, 530.9, 16.3, 31.1),
        1.217 * lobe(lambda, 437.0, 11.8, 36.0) + 0.681 * lobe(lambda, 459.0, 26.0, 13.8)};
}

glm::dvec3 iridescenceFresnel(const ThinFilm& film, const glm::dvec3& baseF0, double cosTheta)
{
    const FilmTerms terms = filmTerms(film, baseF0, cosTheta);
    if (terms.totalReflection)
        return glm::dvec3(1.0);
    glm::dvec3 reflectance = terms.R12 + terms.Rs;
    glm::dvec3 cm = terms.Rs - terms.T121;
    for (int m = 1; m <= 2; ++m) {
        cm *= terms.r123;
        reflectance += cm * 2.0 * evalSensitivity(double(m) * terms.opd, double(m) * terms.phi);
    }
    return glm::max(reflectance, glm::dvec3(0.0));
}

glm::dvec3 iridescenceFresnelSpectral(
    const ThinFilm& film, const glm::dvec3& baseF0, double cosTheta, int wavelengthSamples)
{
    const FilmTerms terms = filmTerms(film, baseF0, cosTheta);
    if (terms.totalReflection)
        return glm::dvec3(1.0);
    const int samples = std::max(wavelengthSamples, 1);
    const double step = (kVisibleLongest - kVisibleShortest) / double(samples);
    glm::dvec3 white(0.0);
    glm::dvec3 channelXyz[3] = {glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
    for (int i = 0; i < samples; ++i) {
        const double lambda = kVisibleShortest + (double(i) + 0.5) * step;
        const glm::dvec3 cmf = colourMatchingFunctions(lambda);
        white += cmf;
        for (int c = 0; c < 3; ++c) {
            // sum_{m >= 1} r^m cos(m x) = Re(z / (1 - z)), z = r e^{ix}.
            const double x = 2.0 * kPi * terms.opd / lambda + terms.phi[c];
            const double r = terms.r123[c];
            const double series = (r * std::cos(x) - r * r) / (1.0 - 2.0 * r * std::cos(x) + r * r);
            const double reflectance = terms.R12 + terms.Rs[c] + 2.0 * (terms.Rs[c] - terms.T121) * series;
            channelXyz[c] += reflectance * cmf;
        }
    }
    const glm::dvec3 whiteRgb = kXyzToRec709 * white;
    glm::dvec3 result;
    for (int c = 0; c < 3; ++c)
        result[c] = (kXyzToRec709 * channelXyz[c])[c] / whiteRgb[c];
    return result;
}

glm::dvec3 wavelengthRgbWeight(double lambda)
{
    // The band's mean colour by the midpoint rule at 0.1 nm, once.
    static const glm::dvec3 mean = [] {
        constexpr int kSteps = 4700;
        const double step = (kVisibleLongest - kVisibleShortest) / double(kSteps);
        glm::dvec3 sum(0.0);
        for (int i = 0; i < kSteps; ++i)
            sum += kXyzToRec709 * colourMatchingFunctions(kVisibleShortest + (double(i) + 0.5) * step);
        return sum / double(kSteps);
    }();
    return (kXyzToRec709 * colourMatchingFunctions(lambda)) / mean;
}

glm::dvec3 thinFilmIncoherentReflectance(const ThinFilm& film, const glm::dvec3& baseF0, double cosTheta)
{
    const FilmTerms terms = filmTerms(film, baseF0, cosTheta);
    if (terms.totalReflection)
        return glm::dvec3(1.0);
    return terms.R12 + terms.Rs;
}

} // namespace facet::shading
