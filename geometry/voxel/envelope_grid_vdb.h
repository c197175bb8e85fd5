#pragma once
// The openvdb side of EnvelopeGrid (geometry/voxel/envelope_grid.h), for the code that needs the grid
// types themselves: mesh export (tools::volumeToMesh) and .vdb files (io::File). Including this
// header costs OpenVDB's compile time; everything else includes envelope_grid.h only.
#include <openvdb/openvdb.h>

#include "geometry/voxel/envelope_grid.h"

namespace fsdb {

struct EnvelopeGrid::Impl {
  openvdb::FloatGrid::Ptr upper;  // u(p), background 0, named "upper"
  openvdb::FloatGrid::Ptr lower;  // l(p), background kNeverInside, named "lower"
  double voxelSize = 0.0;
  EnvelopeGridStats stats;
};

// openvdb::initialize() once per process (std::call_once); every fsdb entry point that makes or
// reads grids calls it, so callers never need to.
void initializeOpenVdb();

inline openvdb::FloatGrid::ConstPtr upperGrid(const EnvelopeGrid& g) { return g.impl().upper; }
inline openvdb::FloatGrid::ConstPtr lowerGrid(const EnvelopeGrid& g) { return g.impl().lower; }

}  // namespace fsdb
