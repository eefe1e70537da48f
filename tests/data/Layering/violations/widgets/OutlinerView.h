#pragma once
#include "templates/HookPoints.h"
