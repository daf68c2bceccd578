#pragma once
// Frames of a converging method (IblMethod::Reference) summed into float targets, so that N
// samples per pixel are the sum of draws of k samples each (docs/rendering.md, "Accumulation").
// Two half-buffers, A and B, take alternate draws: each texel holds the sum of k * mean (alpha,
// the coverage, included); the sums of k are the same for every texel and kept here.
// Their mean is the image; their difference estimates its noise [the dual-buffer estimate of
// Rousselle et al. 2012 and Cycles' adaptive sampling]:
//     var(mean) ~ |mA - mB|^2 nA nB / (nA + nB)^2
// since var(mA - mB) = s^2 (1/nA + 1/nB) and var(mean) = s^2 / (nA + nB). With quasi-random
// points the halves' difference overestimates the error of the whole: the estimate is
// conservative.
//
//   FrameAccumulator accumulator;                // GL context current
//   accumulator.reset(w, h, &error);
//   accumulator.add(frame, k, &error);           // frame: the k-sample mean, w x h
//   accumulator.resolve(out, &error);            // out: the mean of every sample so far
// The passes leave their target bound, blending and depth testing off, unit 0 active.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/image/Image.h"
#include "core/image/ImageMetrics.h"
#include "render/Framebuffer.h"

namespace facet {

class ShaderProgram;

class FrameAccumulator {
public:
    FrameAccumulator();
    ~FrameAccumulator(); // the context must be current
    FrameAccumulator(const FrameAccumulator&) = delete;
    FrameAccumulator& operator=(const FrameAccumulator&) = delete;

    // Empties the sums and sizes the targets to width x height (made on first use or a new size).
    bool reset(int width, int height, std::string* error);
    // Adds `frame` (same size; each texel the mean of `samples` samples) with weight `samples`,
    // into A or B in turn.
    bool add(const Framebuffer& frame, int samples, std::string* error);
    // Writes the mean of everything added into `out` (same size; rgb and the mean coverage: alpha
    // 1 where every draw covered the pixel, as with an opaque background).
    bool resolve(Framebuffer& out, std::string* error);

    int width() const { return m_width; }
    int height() const { return m_height; }
    // Samples per pixel so far, and draws.
    int samples() const { return m_samples; }
    int draws() const { return m_draws; }
    // Samples per pixel in half `half` (0: A, which takes draws 0, 2, 4 ...; 1: B).
    int halfSamples(int half) const { return m_halfSamples[half & 1]; }

    // The noise estimate of the mean with the relative RMSE's normalisation
    // (core/image/ImageMetrics relativeRmse): sqrt(sum var_p / sum |m_p|^2) over the pixels `mask`
    // marks (row-major, top row first, as Image; empty: every pixel), from read-backs of A and B.
    // nullopt before both halves hold a draw.
    std::optional<double> noise(const PixelMask& mask = {}) const;
    // What noise() reads, per pixel: the mean so far (rgb; alpha 1) and the estimated variance of
    // that mean summed over RGB (core/image/ImageMetrics relativeNoise turns it into a relative noise).
    // nullopt before both halves hold a draw.
    struct Spread {
        Image mean;
        std::vector<float> variance;
        int samples = 0; // per pixel in the mean (both halves)
    };
    std::optional<Spread> spread() const;

private:
    bool ensureProgram(std::string* error);

    std::unique_ptr<ShaderProgram> m_program; // ACCUMULATE
    std::unique_ptr<ShaderProgram> m_resolveProgram;
    unsigned m_vao = 0;
    std::optional<Framebuffer> m_halves[2];
    int m_width = 0;
    int m_height = 0;
    int m_samples = 0;
    int m_halfSamples[2] = {0, 0};
    int m_draws = 0;
};

} // namespace facet
