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
    case ConstraintKind::Visibility: return "visibility";
    case ConstraintKind::Roll: return "roll";
    case ConstraintKind::DrivenKey: return "driven_key";
    case ConstraintKind::Carry: return "carry";
    }
    return "parent";
}

const char* rollModeName(RollMode mode) { return mode == RollMode::Axis ? "axis" : "path"; }

const char* showWhenName(ShowWhen when) { return when == ShowWhen::Above ? "above" : "below"; }

const char* curveInfinityName(CurveInfinity infinity)
{
    switch (infinity) {
    case CurveInfinity::Constant: return "constant";
    case CurveInfinity::Linear: return "linear";
    case CurveInfinity::Cycle: return "cycle";
    }
    return "constant";
}

} // namespace rs::model

namespace rs::model {

void forEachNodeIndex(RigConstraint& constraint, const std::function<void(RigNodeIndex&)>& visit)
{
    for (RigNodeIndex& index : constraint.driven)
        visit(index);
    for (RigNodeIndex& index : constraint.targets)
        visit(index);
    auto ref = [&](AttributeRef& attribute) { visit(attribute.node); };
    auto optionalRef = [&](std::optional<AttributeRef>& attribute) {
        if (attribute)
            visit(attribute->node);
    };
    std::visit(
        [&](auto& settings) {
            using T = std::decay_t<decltype(settings)>;
            if constexpr (std::is_same_v<T, BlendConstraint>) {
                ref(settings.weight);
            } else if constexpr (std::is_same_v<T, IkConstraint>) {
                optionalRef(settings.stretch);
                optionalRef(settings.soft);
                optionalRef(settings.volume);
                optionalRef(settings.pin);
            } else if constexpr (std::is_same_v<T, SplineConstraint>) {
                optionalRef(settings.stretch);
                optionalRef(settings.volume);
                optionalRef(settings.slide);
                optionalRef(settings.rigidityStart);
                optionalRef(settings.rigidityEnd);
            } else if constexpr (std::is_same_v<T, SpaceConstraint>) {
                ref(settings.choice);
            } else if constexpr (std::is_same_v<T, VisibilityConstraint>) {
                ref(settings.value);
            } else if constexpr (std::is_same_v<T, RollConstraint>) {
                optionalRef(settings.amount);
            } else if constexpr (std::is_same_v<T, AimConstraint>) {
                optionalRef(settings.weight);
            } else if constexpr (std::is_same_v<T, TwistConstraint>) {
                optionalRef(settings.bias);
            } else if constexpr (std::is_same_v<T, DrivenKeyConstraint>) {
                visit(settings.driver.node);
                visit(settings.driven.node);
            } else if constexpr (std::is_same_v<T, CarryConstraint>) {
                for (RigNodeIndex& carried : settings.carried)
                    visit(carried);
            } else if constexpr (std::is_same_v<T, DriveConstraint>) {
                ref(settings.value);
                std::visit(
                    [&](auto& response) {
                        if constexpr (!std::is_same_v<std::decay_t<decltype(response)>, DriveClamped>)
                            ref(response.breakAngle);
                    },
                    settings.response);
            } else {
                // Parent, orient, point and scale read no attribute.
                static_assert(std::is_same_v<T, ParentConstraint> || std::is_same_v<T, OrientConstraint> ||
                              std::is_same_v<T, PointConstraint> || std::is_same_v<T, ScaleConstraint>);
            }
        },
        constraint.settings);
}

} // namespace rs::model
