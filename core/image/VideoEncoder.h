#pragma once
// A video from a numbered sequence of PNG frames, by ffmpeg (Debian package `ffmpeg`), for
// turntables (`facet render --turntable N -o turn.mp4`, File > Save Turntable…). Facet encodes no
// video itself: where ffmpeg is not installed the caller says so and how to get it
// (missingFfmpegAdvice), and writes the frames instead.
//
// .mp4: H.264 (libx264), yuv420p, CRF 18 (visually lossless), fast start; .webm: VP9 (libvpx-vp9),
// CRF 30, constant quality. yuv420p needs even sides: an odd width or height is padded by one
// black row or column. ffmpeg writes into a temporary folder; the video then goes to its
// destination through core/support/AtomicFile.h, so a failed encode never leaves half a file nor harms an
// existing one.

#include <string>

namespace facet {

// Whether `path` names a video this encoder writes (.mp4, .webm; any case).
bool isVideoPath(const std::string& path);

// The ffmpeg to run: $FACET_FFMPEG when set (tests point it at a missing file), else "ffmpeg" on
// the PATH. Empty when there is none.
std::string findFfmpeg();
// "writing turn.mp4 needs ffmpeg, which is not installed (Debian: sudo apt install ffmpeg); or
// write the frames: -o turn_####.png" (`framesHint` the last part, the caller's words).
std::string missingFfmpegAdvice(const std::string& videoPath, const std::string& framesHint);

// Encodes `framePattern` (an ffmpeg image pattern, e.g. "/tmp/x/frame_%05d.png", frames from 0)
// at `fps` frames a second into `videoPath`. False with *error ("<path>: ffmpeg failed: <its
// last lines>", or missingFfmpegAdvice) on failure.
bool encodeVideo(const std::string& framePattern, int fps, const std::string& videoPath, std::string* error);

} // namespace facet
