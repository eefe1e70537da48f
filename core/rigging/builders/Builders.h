#pragma once
// Built-in template builders, registered by BuilderRegistry::builtin().
#include "rigging/TemplateBuilder.h"

namespace rs::rigging {

// world.character / world.prop: seed 004's base structure (root, controller,
// joint, setup and model groups; world, move, scale, fly; post transform).
std::unique_ptr<TemplateBuilder> makeWorldBuilder();
// world.default: Mikan's default root, a world and a move controller (spaces
// world, move and root) at one guide joint.
std::unique_ptr<TemplateBuilder> makeWorldDefaultBuilder();
// core.joints (and the fallback for modules without a builder): an FK chain,
// one offset group, controller and skin joint per guide joint.
std::unique_ptr<TemplateBuilder> makeJointChainBuilder();
// core.bones: a bone per segment aimed at the next guide joint, the last guide
// joint a tip hook without a controller.
std::unique_ptr<TemplateBuilder> makeBoneChainBuilder();
// core.xform: one controller (or locator) with an optional skin joint, for props.
std::unique_ptr<TemplateBuilder> makeXformBuilder();
// spine.torso: COG, hips, FK spine, IK-style torso (hips, chest) blended per joint.
std::unique_ptr<TemplateBuilder> makeSpineBuilder();
// neck.head: FK neck chain and a head controller with a head-space switch.
std::unique_ptr<TemplateBuilder> makeNeckBuilder();
// arm.limb, leg.limb, quad.leg: the shared limb builder (FK/IK, pole, stretch,
// soft IK, twist and blend joints; legs and quads add a reverse foot).
enum class LimbKind { Arm, Leg, Quad };
std::unique_ptr<TemplateBuilder> makeLimbBuilder(LimbKind kind);
// digit.finger: a finger or toe with a base control and a tip.
std::unique_ptr<TemplateBuilder> makeDigitBuilder();
// digit.hand: a hand master control whose fist, curl, spread and cup drive
// every digit.finger hung on it.
std::unique_ptr<TemplateBuilder> makeHandBuilder();
// rig.spline: a chain following a curve through spline controllers (tails).
std::unique_ptr<TemplateBuilder> makeSplineBuilder();

// wheel.legacy: a wheel that rolls by itself as it travels (d / radius
// radians about its axle), a bank control at the ground and a manual spin.
std::unique_ptr<TemplateBuilder> makeWheelBuilder();
// rig.slide: a control sliding along a rail between two guide joints, within
// limits in metres; what hangs on the rail rides on it.
std::unique_ptr<TemplateBuilder> makeSlideBuilder();
// util.camera: a camera aiming at its target control, with a roll and lens attributes.
std::unique_ptr<TemplateBuilder> makeCameraBuilder();

// face.jaw, face.eye, face.brow, face.mouth: the face's parts on guides placed
// on the head (jaw and chin; an eye aiming at a shared look target, lids
// following the gaze and a blink; a brow; lips and corners the jaw carries).
std::unique_ptr<TemplateBuilder> makeJawBuilder();
std::unique_ptr<TemplateBuilder> makeEyeBuilder();
std::unique_ptr<TemplateBuilder> makeBrowBuilder();
std::unique_ptr<TemplateBuilder> makeMouthBuilder();

// The rest-pose frame of a guide joint: its world matrix without scale or shear.
Mat4 rigidFrame(const Mat4& world);

} // namespace rs::rigging
