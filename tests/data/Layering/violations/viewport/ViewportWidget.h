#pragma once
// allowed: a viewport header and the session
#include "session/Session.h"
