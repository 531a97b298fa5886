// Private: the grammar of Valve's SMD and VTA files (developer.valvesoftware.com/wiki/SMD),
// checked before assimp reads one. assimp 5.2's SMD reader trusts its input: fuzzing found it
// looping forever on a section left open and on blank or indented lines in the nodes section,
// asking for 412 GB for a node index of 88 digits, 7.6 GB for a malformed skeleton line, 26 GB
// for a node that is its own parent and 33 GB for a number of 24 digits, and reading past its
// buffer on control characters, form feeds and a last "end" without a line break.
// assimp only ever sees files that follow the grammar, with indices and times in range.
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>

namespace sphereset::detail {

// Largest node, bone or vertex index, frame time and bone-link count accepted.
inline constexpr int64_t kMaxSmdIndex = 1000000;
// Longest number accepted (characters), and its magnitude at most limits::kMaxCoordinate: a
// coordinate of 31 digits made assimp ask for 19 GB (found by fuzzing).
inline constexpr size_t kMaxSmdNumberChars = 24;
// Most digits before a number's point (or exponent): assimp reads them as one 64-bit integer.
inline constexpr size_t kMaxSmdIntegerDigits = 18;

// What is wrong with the SMD/VTA text in `in`, naming the line ("" when it follows the grammar):
//   version 1
//   nodes            then lines: ID "NAME" PARENT                       then end
//   skeleton         then lines: time T | BONE X Y Z RX RY RZ           then end
//   triangles        then groups: MATERIAL, and three lines
//                    PARENT X Y Z NX NY NZ U V [LINKS (BONE WEIGHT)*LINKS] then end
//   vertexanimation  then lines: time T | VERTEX X Y Z NX NY NZ         then end
// Blank lines and lines starting with "//" are skipped (the nodes section has no blank or
// indented line); integers are
// in [-1, kMaxSmdIndex]; nodes are numbered 0, 1, ... in order, each parent before its child, at
// least one; bones and links name nodes listed before.
std::string smdProblem(std::istream& in);

}  // namespace sphereset::detail
