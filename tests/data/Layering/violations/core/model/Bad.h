#pragma once
#include "base/Math.h"
#include "rigging/RigBuilder.h"
