#pragma once
// The shell skin (sigma units) unless the scene says otherwise, apart from the cell grid that uses
// it, so that the scene's configuration can name it without the engine's SIMD code.
//
// A wider skin means fewer shell exits but more centres to test per search. With shells placed
// ahead of their particles exits are rare, and at rho = 0.37 no other skin is faster in every
// state of the cooling 2D gas (simulate/PERFORMANCE.md "Shells instead of cell crossings"). In 3D
// the centres to test grow as the cube of the reach (27 cells of (sigma + skin)^3), so a thinner
// skin wins (PERFORMANCE.md "Skin in 3D"). The dynamics is exact for any skin.
namespace ggsim {

inline constexpr double kDefaultSkin = 0.7;    // 1D and 2D
inline constexpr double kDefaultSkin3D = 0.3;  // 3D

constexpr double default_skin(int dim) { return dim == 3 ? kDefaultSkin3D : kDefaultSkin; }

}  // namespace ggsim
