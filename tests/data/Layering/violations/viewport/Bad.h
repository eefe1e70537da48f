#pragma once
#include "Scene.h"
#include "widgets/LogPanel.h"
#include "model/Rig.h"
