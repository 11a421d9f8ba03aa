// Standard laminate lay-up notation, e.g. "[45/-45]2S" (the source paper's [theta/-theta]2S).
//
// Order: the first listed ply is the BOTTOM ply (x3 = -h/2) and the list runs upwards to the top
// face (x3 = +h/2), as in section/laminate.hpp. Angles are in degrees, fibre rotated +theta from
// x1 towards x2 about +x3 (material/ply_rotation.hpp).
//
// Grammar (spaces allowed between tokens):
//   layup    := '[' sequence ']' suffix
//   sequence := item ('/' item)*
//   item     := ply ('_' count | '_h')?  |  '(' sequence ')' ('_'? count)?
//   ply      := ('±' | '∓' | '+-' | '-+' | '+' | '-')? number        (|angle| <= 360)
//   suffix   := ('_'? count)? ('S' | 's')?  |  'T'
// "±45" is +45 then -45 ("∓45", "-+45": -45 then +45); a count on a ± ply is refused because
// texts disagree on whether "±45_2" means 45/-45/45/-45 or 45/45/-45/-45: write "(±45)2".
// A suffix count repeats the whole sequence, then 'S' mirrors the result about the mid-plane:
// "[45/-45]2S" = 45/-45/45/-45/-45/45/-45/45. 'T' (total) means the list as written.
// "_h" marks the last ply of a symmetric stack as the mid-plane ply that is not repeated (the
// overbar of printed notation): "[0/90_h]S" = 0/90/0.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "section/laminate.hpp"

namespace si {

// Expands a lay-up string into ply angles in degrees, bottom ply first. Throws an input
// si::Error whose reason quotes the string (its first 80 characters) and gives the 1-based
// character position of the problem, e.g. "lay-up '[45//0]': empty ply at character 5".
// Groups nest at most 64 deep: the parser is recursive and a hostile string must not exhaust
// the stack.
std::vector<double> parse_layup(std::string_view notation);

// A compact notation for a ply list (bottom first) using runs ("0_2"), ± pairs, a repetition
// count and 'S' where they shorten it, every count within the parser's limit of 1000 (longer
// runs become nested groups: 2000 plies at 0 deg print as "[(0_1000)2]"). parse_layup(
// format_layup(a)) == a for every list of 1 to 100,000 finite angles with |angle| <= 360 (the
// parser's limits). Throws an input si::Error for an empty list or a bad angle.
std::string format_layup(const std::vector<double>& angles_deg);

// A short label for reports: the compact notation when every ply has the same material and
// thickness, otherwise "ply list (N plies)".
std::string describe_laminate(const Laminate& laminate);

}  // namespace si
