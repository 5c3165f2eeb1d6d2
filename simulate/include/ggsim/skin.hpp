#pragma once
// The shell skin (sigma units) unless the scene says otherwise, apart from the cell grid that uses
// it, so that the scene's configuration can name it without the engine's SIMD code.
//
// A wider skin means fewer shell exits but more centres to test per search. With shells placed
// ahead of their particles exits are rare, and at rho = 0.37 no other skin is faster in every
// state of the cooling gas (simulate/PERFORMANCE.md "Shells instead of cell crossings"). The
// dynamics is exact for any skin.
namespace ggsim {

inline constexpr double kDefaultSkin = 0.7;

}  // namespace ggsim
