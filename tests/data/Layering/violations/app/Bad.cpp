// the composition root may include every layer, but no format library
#include <assimp/scene.h>
#include "rigging/RigBuilder.h"
#include "ViewportWidget.h"
#include "OutlinerView.h"
