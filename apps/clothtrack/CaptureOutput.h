#pragma once
// The capture part of an output folder, shared by 'synth' and 'simulate-capture':
//   OUT/frames/frame_NNNN.obj      the captured frame (what a multi-view system delivers)
//   OUT/source_map/frame_NNNN.vtp  the same mesh with the ground-truth point of every vertex
#include "ctCaptureSimulation.h"

#include <string>

namespace clothtrack::app
{
/// "frame_NNNN" for frame index k.
std::string frameStem(long k);

/// Creates OUT/frames and OUT/source_map (and any extra sub-folders); UsageError on failure.
/// Point clouds have no source map (`withSourceMap` false).
void makeOutputFolders(const std::string& output, std::initializer_list<const char*> extra = {},
                       bool withSourceMap = true);

/// Simulates the capture of `truth` for frame k and writes both files (atomically).
void captureAndWrite(const std::string& output, long k, const TriangleMesh& truth,
                     CaptureOptions options, unsigned seed);
} // namespace clothtrack::app
