#include "model/Constraint.h"

namespace rs::model {

const char* axisName(Axis axis)
{
    switch (axis) {
    case Axis::X: return "x";
    case Axis::Y: return "y";
    case Axis::Z: return "z";
    }
    return "x";
}

const char* driveOutputName(DriveOutput output)
{
    switch (output) {
    case DriveOutput::RotateX: return "rotate_x";
    case DriveOutput::RotateY: return "rotate_y";
    case DriveOutput::RotateZ: return "rotate_z";
    case DriveOutput::Scale: return "scale";
    }
    return "rotate_x";
}

const char* constraintKindName(ConstraintKind kind)
{
    switch (kind) {
    case ConstraintKind::Parent: return "parent";
    case ConstraintKind::Orient: return "orient";
    case ConstraintKind::Point: return "point";
    case ConstraintKind::Blend: return "blend";
    case ConstraintKind::Ik: return "ik";
    case ConstraintKind::Twist: return "twist";
    case ConstraintKind::Spline: return "spline";
    case ConstraintKind::Space: return "space";
    case ConstraintKind::Drive: return "drive";
    case ConstraintKind::Aim: return "aim";
    case ConstraintKind::Scale: return "scale";
    }
    return "parent";
}

} // namespace rs::model
