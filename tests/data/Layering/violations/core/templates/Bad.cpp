// planted: templates reading YAML itself
#include "io/YamlSupport.h"
#include <yaml-cpp/yaml.h>
#include "base/TextScalars.h"
