// The names a scene file gives the CDEM model's choices, read by
// scene_cdem.cpp and written by scene_write.cpp from these one tables.
#pragma once
#include <utility>

#include "dda/cdem/model.hpp"

namespace dda::io::detail {

template <class E>
using NameTable = std::pair<const char*, E>[2];

inline constexpr NameTable<cdem::ContactMode> kCdemContact = {{"two_scale", cdem::ContactMode::kTwoScale},
                                                              {"node_to_edge_penalty", cdem::ContactMode::kNodeToEdgePenalty}};
inline constexpr NameTable<cdem::TouchImpact> kTouchImpact = {{"perfectly_inelastic", cdem::TouchImpact::kPerfectlyInelastic},
                                                              {"coulomb", cdem::TouchImpact::kCoulomb}};
inline constexpr NameTable<cdem::SubdivisionMode> kSubdivisionMode = {{"submodel", cdem::SubdivisionMode::kSubModel},
                                                                      {"in_place", cdem::SubdivisionMode::kInPlace}};
inline constexpr NameTable<cdem::PatchDeletion> kPatchDeletion = {{"at_separation", cdem::PatchDeletion::kAtSeparation},
                                                                  {"energy_matched", cdem::PatchDeletion::kEnergyMatched}};

template <class E>
const char* name_in(const NameTable<E>& table, E value) {
  for (const auto& [name, v] : table)
    if (v == value) return name;
  return table[0].first;
}

}  // namespace dda::io::detail
