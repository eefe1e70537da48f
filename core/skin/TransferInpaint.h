#pragma once
// Internal to skin/Transfer (TransferMethods.cpp): the inpainting step of
// robust weight transfer (Abdrashitov et al., "Robust Skin Weights Transfer
// via Weight Inpainting", SIGGRAPH Asia 2023). Target vertices whose closest
// source point was near and faced their way keep their copied weights; the
// others' weights minimise the squared-Laplacian energy tr(W' Q W),
// Q = L + L M^-1 L (L the target's cotangent Laplacian on its welded surface,
// M its vertex areas), with the kept ones fixed. The unknowns split into the
// regions Q connects; each region is factorised once (CHOLMOD) and solved for
// the joints its known neighbours carry. A connected part with no kept vertex
// keeps its copied weights (nothing to inpaint from).
#include "base/Result.h"
#include "model/Mesh.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace rs::skin {

// `slots` holds `capacity` influences per file vertex of `target`, `counts`
// how many are used; the vertices not `matched` are rewritten (at most
// `capacity` influences, normalised). Returns how many file vertices were
// inpainted (and, with `inpaintedVertices`, appends their ids, ascending);
// fails (slots unchanged) when a system cannot be factorised or `progress`
// (optional; hears the fraction of the inpainting done, from the calling
// thread, between regions and joint groups) returns false.
Result<std::size_t> inpaintWeights(const model::Mesh& target, const std::vector<std::uint8_t>& matched, int capacity,
                                   std::vector<model::Influence>& slots, std::vector<std::uint8_t>& counts,
                                   const std::function<bool(double)>& progress = {},
                                   std::vector<std::uint32_t>* inpaintedVertices = nullptr);

} // namespace rs::skin
