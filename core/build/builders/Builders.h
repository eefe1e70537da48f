#pragma once
// Built-in template builders, registered by BuilderRegistry::builtin().
#include "build/TemplateBuilder.h"

namespace rs::build {

// world.character / world.prop: world and move controllers, a root skin joint.
std::unique_ptr<TemplateBuilder> makeWorldBuilder();
// core.joints (and the fallback for modules without a builder): an FK chain,
// one offset group, controller and skin joint per guide joint.
std::unique_ptr<TemplateBuilder> makeJointChainBuilder();

// The rest-pose frame of a guide joint: its world matrix without scale or shear.
Mat4 rigidFrame(const Mat4& world);

} // namespace rs::build
