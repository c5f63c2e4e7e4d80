#ifndef ctBuiltinBodyModel_h
#define ctBuiltinBodyModel_h
// The built-in body model, made by the project's own code: the procedural mean body is
// polygonised (flying edges on its signed distance), smoothed and decimated to about 10k
// vertices, then the statistical model is learned from it (see BodyModelBuilder.h).
// C++ only (not wrapped).
#include "ctFiltersModule.h"

#include <clothtrack/body/BodyModel.h>
#include <clothtrack/body/ProceduralBody.h>

namespace clothtrack
{
/// Polygonises the procedural mean body: a closed genus-0 manifold mesh in rest pose.
CTFILTERS_EXPORT TriangleMesh proceduralBodyMesh(double stature = 1.72, int targetVertices = 10000);

/// The built-in model, built on first use (a few seconds) and shared afterwards; thread-safe.
CTFILTERS_EXPORT const BodyModel& builtinBodyModel();

/// A model built as the built-in one, from a population of the given spread (a few seconds each
/// call): `clothtrack body-model --spread` writes it as a model file for `--model`.
CTFILTERS_EXPORT BodyModel proceduralBodyModel(const BodySpread& spread);
} // namespace clothtrack

#endif
