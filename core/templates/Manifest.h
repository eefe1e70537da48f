#pragma once
// A template manifest (templates/<category>/<module>/template.yml) as typed data.
// Format: Mikan's template.yml (see ../shared/reference/mikan-format.md §1).
// Maps keep the file's order, so UIs list things as the author wrote them.
#include "base/Diagnostic.h"
#include "model/Value.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rs::templates {

// One `guides` or `opts` entry.
struct Parameter {
    std::string name;
    Value value;                          // default; its type is the parameter's type
    std::optional<double> min, max;       // clamps for numbers
    std::vector<std::pair<long long, std::string>> enumLabels; // index -> label
    bool yaml = false;                    // value is flow-YAML text parsed on read
    std::string help;
    std::vector<std::string> presets;
    std::string legacy;                   // another name it loads under (an old one, or Mikan's where ours differs)
    SourceLocation where;

    bool isEnum() const { return !enumLabels.empty(); }
};

// One `shapes` entry: the default curve of the controller registered as `key`.
struct ShapeSpec {
    std::string key;      // controller id, e.g. "ctrls.world", may hold '*'
    std::string shape;    // shape library name
    std::string color;    // CSS name or #hex; empty = library colour
    double size = 1.0;    // largest extent of the curve, metres
    std::string parent;   // structure tag holding the shape in the guide
    std::vector<std::string> point;
    std::string aim, up;                  // structure or world axis ("y", "-x")
    std::string aimAxis = "+y", upAxis;   // local axes of the shape
    std::vector<std::pair<std::string, std::vector<std::string>>> doAim; // aim only if these opts match
    std::string clone;                    // copy this controller's curves, then apply size (relative) and colour
    std::string reference;                // the curves land on this controller id instead of `key`
    // The library's Y axis is turned onto this axis ("x", "-z"), or onto the
    // value of the option it names ("aim_axis": a circle rings the chain
    // whichever axis aims), if `doAxis` allows.
    std::string axis;
    std::vector<std::pair<std::string, std::vector<std::string>>> doAxis; // turn only if these opts match
    SourceLocation where;
};

// "x", "+y", "-z" -> unit vector; nullopt for anything else.
std::optional<Vec3> parseAxis(const std::string& text);

// Overrides applied to a hierarchy entry when its `opts` condition holds.
struct HierarchyRule {
    std::optional<bool> root;
    std::optional<std::vector<std::string>> parent;
    std::optional<std::vector<std::string>> hook;
    std::optional<bool> chain;
};

// One `hierarchy` entry: where a rig node (or id branch) sits in the virtual hierarchy.
struct HierarchyEntry {
    std::string id;                       // "ctrls.world", "skin.up" (branch) ...
    HierarchyRule base;
    std::vector<std::pair<std::string, HierarchyRule>> conditional; // expression -> overrides
    SourceLocation where;

    std::string domain() const { return id.substr(0, id.find('.')); }
};

struct UiHook {
    std::string label;      // "default" is the attach point of the template itself
    std::string structure;  // structure address
};

struct TemplateManifest {
    std::string id;         // "category.module", from the folder names
    std::string category, module;
    std::string file;       // path of template.yml
    std::string directory;

    std::string name;       // default instance name
    std::string desc, help, base;
    std::vector<std::pair<std::string, std::string>> names;      // token -> default name
    std::vector<std::pair<std::string, std::string>> structure;  // tag -> address
    std::vector<Parameter> guides;
    std::vector<Parameter> opts;  // own opts followed by the common options
    std::vector<ShapeSpec> shapes;
    std::vector<HierarchyEntry> hierarchy;
    std::string icon;             // file name in resources/icons (no extension)
    SourceLocation iconWhere;
    std::vector<UiHook> hooks;

    const Parameter* findOpt(const std::string& name) const;
    const Parameter* findGuide(const std::string& name) const;
    // The option or guide parameter whose other name (`legacy`) this is: iks for rig.spline's controls.
    const Parameter* findByOtherName(const std::string& name) const;
    const ShapeSpec* findShape(const std::string& key) const;
    std::string defaultName(const std::string& token) const;
    std::optional<std::string> structureAddress(const std::string& tag) const;
};

} // namespace rs::templates
