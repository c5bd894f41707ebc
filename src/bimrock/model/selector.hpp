#pragma once
/// @file Choosing boundary edges or interfaces by where they are: on a line, inside a box, by
/// the orientation of their trace, or on the line elements of a mesh's physical curve.
#include <string>
#include <vector>

#include <bimrock/geometry/bbox.hpp>
#include <bimrock/geometry/segment.hpp>
#include <bimrock/model/errors.hpp>

namespace bimrock {

struct Selector {
  enum class Kind {
    all,          ///< every segment
    line,         ///< segments lying on `line` (both ends within tol of the segment `line`)
    box,          ///< segments with both ends inside `box` (grown by tol)
    orientation,  ///< segments whose trace makes `angle_deg` (mod 180) with the x-axis
    group,        ///< segments lying on one of `segments` (the line elements of a mesh group)
  };
  Kind kind = Kind::all;
  Segment line;
  BBox box;
  double angle_deg = 0.0;
  double angle_tolerance_deg = 1.0;
  std::string group;              ///< the name of the physical curve (kind group)
  std::vector<Segment> segments;  ///< its line elements [m], filled when the mesh is read
  SourceRef source;
};

/// True when the selector picks segment s (tol: the model's length tolerance).
bool selects(const Selector& sel, const Segment& s, double tol);

}  // namespace bimrock
