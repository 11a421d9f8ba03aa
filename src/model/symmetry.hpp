// Which part of an axisymmetric model is meshed. A quarter model is valid only for a laminate
// that is specially orthotropic in the model axes (paper-notes.md, item 2): angle-ply stacks
// have bending-twisting coupling and no mirror symmetry.
#pragma once

namespace si {

enum class Symmetry {
  kFull,     // the whole disk
  kQuarter,  // the part x >= 0, y >= 0
};

}  // namespace si
