#pragma once
// Internal to skin/Transfer (TransferMethods.cpp): the inpainting step of
// robust weight transfer (Abdrashitov et al., "Robust Skin Weights Transfer
// via Weight Inpainting", SIGGRAPH Asia 2023). Target vertices whose closest
// source point was near and faced their way keep their copied weights; the
// others' weights minimise the squared-Laplacian energy tr(W' Q W),
// Q = L + L M^-1 L (L the target's cotangent Laplacian on its welded surface,
// M its vertex areas), with the kept ones fixed: one sparse LDL' factorisation,
// every joint a right-hand side. A connected part with no kept vertex keeps
// its copied weights (nothing to inpaint from).
#include "base/Result.h"
#include "model/Mesh.h"

#include <cstdint>
#include <vector>

namespace rs::skin {

// `slots` holds `capacity` influences per file vertex of `target`, `counts`
// how many are used; the vertices not `matched` are rewritten (at most
// `capacity` influences, normalised). Returns how many file vertices were
// inpainted; fails (slots unchanged) when the system cannot be factorised.
Result<std::size_t> inpaintWeights(const model::Mesh& target, const std::vector<std::uint8_t>& matched, int capacity,
                                   std::vector<model::Influence>& slots, std::vector<std::uint8_t>& counts);

} // namespace rs::skin
