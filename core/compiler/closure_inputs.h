// How a plain material's description becomes its compiled material (docs/architecture.md,
// "Parameter tables"): the settings block both derive from, copied whole, and each colour
// input paired with the texture it compiles to. A closure node's valued inputs land in
// the same places, found by socket name from the rows of the description's table, so a
// new setting of a closure needs no line here.
#pragma once

#include "core/document/material_desc.h"
#include "core/materials/material.h"

#include <array>
#include <string_view>

namespace inkray {

// A colour input of description D and the texture of material M it compiles to.
template <class D, class M>
struct TextureSlot {
  ColorInput D::*input;
  Texture M::*texture;
};

// What CompiledMaterial<D> says: D compiles to M, copying the block P (void: no block),
// and its colour inputs to `textures` (none unless the specialisation lists them).
template <class D, class M, class P = void>
struct CompilesTo {
  using type = M;
  using Params = P;
  using Slot = TextureSlot<D, M>;
  static constexpr std::array<Slot, 0> textures{};
};

// No general definition: a plain material's description that does not say what it
// compiles to does not compile (compile_materials.cpp visits every one).
template <class D>
struct CompiledMaterial;
template <>
struct CompiledMaterial<DiffuseDesc> : CompilesTo<DiffuseDesc, DiffuseMaterial> {
  static constexpr std::array textures{Slot{&DiffuseDesc::albedo, &DiffuseMaterial::albedo}};
};
template <>
struct CompiledMaterial<ConductorDesc> : CompilesTo<ConductorDesc, ConductorMaterial, ConductorParams> {
  static constexpr std::array textures{Slot{&ConductorDesc::color, &ConductorMaterial::color}};
};
template <>
struct CompiledMaterial<DielectricDesc> : CompilesTo<DielectricDesc, DielectricMaterial, DielectricParams> {};
template <>
struct CompiledMaterial<EmissiveDesc> : CompilesTo<EmissiveDesc, EmissiveMaterial, EmissiveParams> {
  static constexpr std::array textures{Slot{&EmissiveDesc::color, &EmissiveMaterial::color}};
};
template <>
struct CompiledMaterial<UnlitDesc> : CompilesTo<UnlitDesc, UnlitMaterial> {
  static constexpr std::array textures{Slot{&UnlitDesc::color, &UnlitMaterial::color}};
};
template <>
struct CompiledMaterial<TransparentDesc>
    : CompilesTo<TransparentDesc, TransparentMaterial, TransparentParams> {};
// The ramps are compiled on their own (compile_materials.cpp).
template <>
struct CompiledMaterial<ToonDesc> : CompilesTo<ToonDesc, ToonMaterial, ToonParams> {
  static constexpr std::array textures{Slot{&ToonDesc::color, &ToonMaterial::color}};
};
// Its sides' indices are set once every material is compiled.
template <>
struct CompiledMaterial<MixDesc> : CompilesTo<MixDesc, MixMaterial> {
  static constexpr std::array textures{Slot{&MixDesc::factor, &MixMaterial::factor}};
};

// The setter of the valued input `socket` of a closure node of type `type` (its JSON
// "type", DiffuseDesc::type_name and the like); null when there is no such input
// (tests/compiler/closure_inputs_test.cpp checks every closure node's valued sockets
// have one).
ClosureSetter closure_input_setter(std::string_view type, std::string_view socket);

}  // namespace inkray
