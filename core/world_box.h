#pragma once
// The world-space box around an index box's outer voxel faces, from all eight corners through
// the transform: a rotated grid's box holds it (two corners alone miss it: a slab turned 45°
// read z ±0.035 where it spans ±0.728). `eikon info` and the automatic camera both need it.
#include <algorithm>

#include <openvdb/math/BBox.h>
#include <openvdb/math/Coord.h>
#include <openvdb/math/Transform.h>

namespace eikon {

inline openvdb::BBoxd worldBoxOf(const openvdb::math::Transform& xform,
                                 const openvdb::CoordBBox& box) {
    const openvdb::Vec3d lo = box.min().asVec3d() - 0.5, hi = box.max().asVec3d() + 0.5;
    openvdb::BBoxd out;
    for (int corner = 0; corner < 8; ++corner) {
        const openvdb::Vec3d p = xform.indexToWorld(openvdb::Vec3d(corner & 1 ? hi.x() : lo.x(),
                                                                   corner & 2 ? hi.y() : lo.y(),
                                                                   corner & 4 ? hi.z() : lo.z()));
        if (corner == 0)
            out = openvdb::BBoxd(p, p);
        else
            out.expand(p);
    }
    return out;
}

}  // namespace eikon
