#pragma once
// A body pose turned half round in place: facing the other way while its limbs keep to where the
// given pose's limbs lie.
#include "BodyModel.h"

namespace clothtrack
{
/// The joint on the other side of the body (left_elbow for right_elbow); a joint on the midline
/// is its own opposite.
int oppositeJoint(int joint);

/// `pose` turned half round about the body's own up axis through the pelvis, each joint taking
/// its opposite's rotation turned the same way: the left arm goes where the right arm was, bent
/// as the right arm was seen from behind. On a body symmetric about its midline the turned pose
/// covers the surface that `pose` covers, with front and back and left and right exchanged: the
/// start from which a fit left facing backwards can settle facing forwards without its limbs
/// crossing to the other side. `restJoints` (NumJoints x 3, the model's rest pose) gives the up
/// axis (pelvis to neck).
BodyPose turnedInPlace(const BodyPose& pose, const Points& restJoints);
} // namespace clothtrack
