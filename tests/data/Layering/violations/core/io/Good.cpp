// allowed: io reads YAML and knows templates
#include "io/YamlSupport.h"
#include <yaml-cpp/yaml.h>
#include <assimp/scene.h>
#include "templates/Manifest.h"
