#pragma once
// Whether a frame looks like a standing person in metres, and the unit and up axis under which it
// would. A capture in centimetres read as metres is a 175 m giant, one with Z up read as Y up a
// person lying down; both run to the end with every body fit poor unless told.
#include <clothtrack/mesh/TriangleMesh.h>

#include <string>
#include <vector>

namespace clothtrack
{
/// The heights, in metres, taken as a person's: from a child to a tall adult with raised arms.
constexpr double kSmallestPerson = 0.8;
constexpr double kTallestPerson = 2.6;

/// The up axis (0, 1, 2 for x, y, z) that a standing subject suggests: the bounding box's longest
/// side. A person with arms spread is about as wide as tall; then y, the usual convention, wins
/// when it is within 10 % of the longest.
int inferUpAxis(const TriangleMesh& mesh);

/// The metres per file unit, among m, dm, cm and mm, under which the subject's extent along
/// `upAxis` is a person's height; 0 when none is.
double inferUnitScale(const TriangleMesh& mesh, int upAxis);

/// The name of a unit scale from inferUnitScale ("m", "dm", "cm", "mm").
const char* unitName(double unitScale);

/// Warnings about a frame already in metres with Y up: a height no person has (with the unit
/// that would give one), or a subject longer across than tall (lying, or another up axis).
std::vector<std::string> subjectWarnings(const TriangleMesh& metresYUp);
} // namespace clothtrack
