#pragma once
// Sample generation and importance sampling, in double. The GGX samplers, the low-discrepancy
// points and the hash have GLSL twins of the same names in resources/shaders/common_sampling.glsl
// (the search of an environment's sampling tables: core/ibl/EnvironmentSamplingTables.h and
// resources/shaders/environment_sampling.glsl). Directions in "tangent space" have the surface
// normal along +Z; buildOrthonormalBasis() takes them to world space.
//
// Every sampler returns its pdf with respect to solid angle, so Monte Carlo estimators and
// multiple importance sampling can mix them (tests/SamplingTest.cpp integrates each pdf to 1 and
// checks the histograms of the samples against it).

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace facet::sampling {

// ---- Low-discrepancy points -----------------------------------------------------------------

// Van der Corput radical inverse in base 2: the bits of i mirrored about the binary point.
double radicalInverse(std::uint32_t i);
// The i-th point of the Halton sequence in bases 2 and 3, in [0, 1)^2 [Halton 1960]: the
// sub-pixel offsets of accumulated draws (any prefix spreads over the pixel).
glm::dvec2 halton23(std::uint32_t i);
// The i-th of n Hammersley points: (i / n, radicalInverse(i)) [Hammersley & Handscomb 1964].
glm::dvec2 hammersley(std::uint32_t i, std::uint32_t n);
// Randomised quasi-Monte Carlo: the i-th of n Hammersley points shifted by `shift` modulo 1
// (a Cranley-Patterson rotation): unbiased like independent points, with an error that falls
// faster on smooth integrands. The ground truths draw their first surface's points with it.
glm::dvec2 shiftedHammersley(std::uint32_t i, std::uint32_t n, const glm::dvec2& shift);

// The first two dimensions of the Sobol' sequence as 32-bit fixed-point fractions: x is the
// radical inverse of s (dimension 1, van der Corput), y is dimension 2 (primitive polynomial
// x + 1: direction numbers v_1 = 2^31, v_{k+1} = v_k ^ (v_k >> 1); y = XOR of v_k over the set
// bits k of s) [Sobol' 1967; Kollig & Keller 2002, "Efficient Multidimensional Sampling"]. The
// sequence is a (0, 2)-sequence in base 2: every block [k 2^m, (k+1) 2^m) of it, the prefix of
// 2^m points in particular, is a (0, m, 2)-net (each 2^a x 2^(m-a) grid of boxes holds exactly
// one point), so samples accumulated over frames are stratified like one set of the same size.
glm::uvec2 sobol2DBits(std::uint32_t s);
// sobol2DBits(s) / 2^32, exact: in [0, 1).
glm::dvec2 sobol2D(std::uint32_t s);

// The "pcg" hash of Jarzynski & Olano 2020, "Hash Functions for GPU Rendering", JCGT 9(3): one
// step of a PCG LCG followed by its RXS-M-XS output permutation; a bijection of 32-bit values.
std::uint32_t pcgHash(std::uint32_t value);

// One Cranley-Patterson shift (a 2D offset, 32-bit fixed point) for a pixel, a seed and a
// sampling strategy (e.g. 0 BRDF, 1 environment), so that pixels and strategies are decorrelated
// while every pixel keeps the stratification of the shared sequence. Nested hashing of the four
// inputs, as Jarzynski & Olano suggest for multi-dimensional input (section 2): h =
// pcgHash(x + pcgHash(y + pcgHash(seed + pcgHash(strategy)))), shift = (h, pcgHash(h)).
glm::uvec2 cranleyPattersonShift(
    std::uint32_t x, std::uint32_t y, std::uint32_t seed, std::uint32_t strategy);
// Sample s of the shifted sequence as the GPU computes it: (sobol2DBits(s) + shift) mod 2^32,
// i.e. frac(sobol2D(s) + shift / 2^32) without rounding, truncated to 24 bits so that every value
// is an exact float in [0, 1) (a float conversion of 32 bits would round 0.99999999 up to 1).
glm::dvec2 shiftedSobol2D(std::uint32_t s, const glm::uvec2& shift);

// A small, fast, seedable generator (PCG32, O'Neill 2014) for the ground-truth integrator:
// deterministic for a given seed and stream, independent between pixels.
class Pcg32 {
public:
    explicit Pcg32(std::uint64_t seed = 0x853c49e6748fea9bULL, std::uint64_t stream = 0xda3e39cb94b95bdbULL);
    std::uint32_t nextUInt();
    // Uniform in [0, 1).
    double nextDouble();
    glm::dvec2 next2D() { return {nextDouble(), nextDouble()}; }

private:
    std::uint64_t m_state = 0;
    std::uint64_t m_increment = 0;
};

// Whether every channel of an estimate is a finite number (a sample to keep).
bool isFinite(const glm::dvec3& c);

// ---- Frames -----------------------------------------------------------------------------------

// An orthonormal basis (t, b, n) around unit n without branches on degenerate cases
// [Duff et al. 2017, "Building an Orthonormal Basis, Revisited"].
void buildOrthonormalBasis(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b);
glm::dvec3 tangentToWorld(const glm::dvec3& v, const glm::dvec3& t, const glm::dvec3& b, const glm::dvec3& n);
glm::dvec3 worldToTangent(const glm::dvec3& v, const glm::dvec3& t, const glm::dvec3& b, const glm::dvec3& n);

// Reflects v about h (both unit, pointing away from the surface): 2 (v.h) h - v.
glm::dvec3 reflectAbout(const glm::dvec3& v, const glm::dvec3& h);

// ---- Hemisphere and sphere ----------------------------------------------------------------

// Cosine-weighted hemisphere (Malley's method through a concentric disk mapping, Shirley &
// Chiu 1997); pdf = cos(theta) / pi.
glm::dvec3 sampleCosineHemisphere(const glm::dvec2& u);
double pdfCosineHemisphere(double cosTheta);
// Uniform sphere; pdf = 1 / (4 pi).
glm::dvec3 sampleUniformSphere(const glm::dvec2& u);

// ---- GGX ----------------------------------------------------------------------------------------

// Samples a GGX microfacet normal h in tangent space proportionally to D(h) (h.n): the classic
// NDF sampling [Walter et al. 2007, eq. 35-36]. The reflected direction l = reflect(v, h) has
// pdf_l = D(h) (n.h) / (4 v.h) (the Jacobian of reflection, Walter eq. 14).
glm::dvec3 importanceSampleGGX(const glm::dvec2& u, double alpha);
double pdfGGXReflection(double NoH, double VoH, double alpha);

// Samples a GGX normal visible from v (tangent space, v.z > 0) proportionally to
// G1(v) max(0, v.h) D(h) / (n.v) [Heitz 2018, "Sampling the GGX Distribution of Visible
// Normals", JCGT 7(4)]. The reflected direction has pdf_l = G1(v) D(h) / (4 n.v): no sample is
// wasted below the horizon or on back-facing microfacets, which matters at grazing angles.
glm::dvec3 importanceSampleVNDF(const glm::dvec2& u, const glm::dvec3& v, double alpha);
// The same with a roughness per tangent axis (alphaX along x, alphaY along y): the anisotropic
// GGX's visible normals (core/shading/Anisotropy.h); the stretch takes one alpha per axis.
glm::dvec3 importanceSampleVNDF(const glm::dvec2& u, const glm::dvec3& v, double alphaX, double alphaY);
// The same distribution by spherical caps [Dupuy and Benyoub 2023, "Sampling Visible GGX Normals
// with Spherical Caps", HPG, listing 3]: a point of the cap of the unit sphere below the stretched
// view's horizon, added to the view, is the stretched visible normal. No frame is built around
// the view, so the points u map to move continuously with v: Heitz's frame turns with v's azimuth
// and, where n = v (the middle of a sphere facing the camera), a fixed set of points turned a full
// circle around one pixel and drew a pinch in FIS's structured error (issue 29).
glm::dvec3 importanceSampleVNDFSphericalCap(const glm::dvec2& u, const glm::dvec3& v, double alpha);
double pdfVNDFReflection(double NoV, double NoH, double alpha);
// Smith G1 for GGX, exact [Walter et al. 2007, eq. 34].
double G1_SmithGGX(double NoX, double alpha);

// ---- Piecewise-constant distributions (Pharr, Jakob, Humphreys, PBRT 3rd ed., 13.3 and 14.2) ----

class Distribution1D {
public:
    Distribution1D() = default;
    // Weights must be finite and non-negative; all-zero weights give a uniform distribution.
    explicit Distribution1D(std::span<const double> weights);
    std::size_t size() const { return m_weights.size(); }
    double integral() const { return m_integral; }
    // The normalised cumulative distribution, size() + 1 entries from 0 to exactly 1 (uniform
    // steps when every weight is zero): what sampleContinuous searches.
    std::span<const double> cdf() const { return m_cdf; }
    // Continuous sample in [0, 1): returns x, its density (w.r.t. x in [0,1)) and the cell.
    double sampleContinuous(double u, double* pdf, std::size_t* cell) const;
    double pdf(std::size_t cell) const;

private:
    std::vector<double> m_weights;
    std::vector<double> m_cdf; // size n + 1
    double m_integral = 0.0;
};

class Distribution2D {
public:
    Distribution2D() = default;
    // Row-major weights, `height` rows of `width` cells; row 0 is v in [0, 1/height).
    Distribution2D(std::span<const double> weights, std::size_t width, std::size_t height);
    // Samples (x, y) in [0,1)^2 with density pdf w.r.t. area of the unit square.
    glm::dvec2 sampleContinuous(const glm::dvec2& u, double* pdf) const;
    double pdf(const glm::dvec2& xy) const;

    std::size_t width() const { return m_width; }
    std::size_t height() const { return m_height; }
    // The distribution of rows (y), and of x within row `row` (0 .. height() - 1).
    const Distribution1D& marginal() const { return m_marginal; }
    const Distribution1D& conditional(std::size_t row) const { return m_conditional[row]; }

private:
    std::vector<Distribution1D> m_conditional; // one per row
    Distribution1D m_marginal;
    std::size_t m_width = 0;
    std::size_t m_height = 0;
};

} // namespace facet::sampling
