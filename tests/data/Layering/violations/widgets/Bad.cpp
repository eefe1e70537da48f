#include "OutlinerView.h"
#include <yaml-cpp/yaml.h>
#include "ViewportWidget.h"
#include "rigging/BranchStage.h"
