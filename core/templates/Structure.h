#pragma once
// Resolves manifest `structure` addresses to an instance's guide joints.
//   .        the root          /N, /-N  node N of the root's single-child chain
//   /*       the whole chain   (empty)  joints explicitly tagged with the tag
//   tag      another tag       tag[i], tag[a:b], tag[*]  index, slice, all
//   a+b      concatenation
// The chain follows the only untagged, non-helper ("_name") child and stops at
// forks; other templates' roots are never part of it (they belong to their own
// instance). It never relies on sibling order. An instance may override any tag's
// address. Unknown tags, bad syntax and cycles are reported.
//
// A resolver memoises the chain and every tag it resolved, so asking for
// `chain[i]` once per joint stays linear; the manifest and the instance must
// outlive it and not change while it is used.
#include "base/Result.h"
#include "model/GuideDocument.h"
#include "templates/Manifest.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rs::templates {

// One term of an address: `base` is ".", "/N", "/*" or a tag; `selector` the
// text inside [] (empty when none).
struct AddressTerm {
    std::string text, base, selector;
};
// Syntax only; an empty address (explicit tag) gives no terms. A failure's
// error has no file position: the caller knows where the address was written.
Result<std::vector<AddressTerm>> parseAddress(const std::string& expression);

class StructureResolver {
public:
    StructureResolver(const TemplateManifest& manifest, const model::TemplateInstance& instance)
        : m_manifest(manifest), m_instance(instance) {}

    // Joints of a structure tag; a failure (no file position) says why it cannot resolve.
    Result<std::vector<model::JointId>> tag(const std::string& tagName) const;
    // Joints of an address expression as written in `ui.hooks` or `structure`.
    Result<std::vector<model::JointId>> address(const std::string& expression) const;
    const std::vector<model::JointId>& chain() const;

private:
    // The memoised joints of a tag, or nullptr with `error` set.
    const std::vector<model::JointId>* lookup(const std::string& tagName, std::string& error) const;
    std::optional<std::vector<model::JointId>> evaluate(const std::string& expression, const std::string& ownTag,
                                                        std::string& error) const;
    const TemplateManifest& m_manifest;
    const model::TemplateInstance& m_instance;
    mutable std::size_t m_depth = 0; // nesting of tag lookups, to detect cycles
    mutable std::optional<std::vector<model::JointId>> m_chain;
    // Tags that resolved (failures are not kept: a cycle's message depends on where it is entered).
    mutable std::map<std::string, std::vector<model::JointId>, std::less<>> m_tags;
};

} // namespace rs::templates
