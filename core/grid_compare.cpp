#include "core/grid_compare.h"

#include <openvdb/openvdb.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "core/error.h"
#include "core/vdb_reader.h"

namespace eikon {
namespace {

using openvdb::Coord;

double magnitude(float v) {
    return double(v);
}
double magnitude(double v) {
    return v;
}
double magnitude(const openvdb::Vec3s& v) {
    return double(v.length());
}

double difference(float a, float b) {
    return std::fabs(double(a) - double(b));
}
double difference(double a, double b) {
    return std::fabs(a - b);
}
double difference(const openvdb::Vec3s& a, const openvdb::Vec3s& b) {
    double d = 0.0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::fabs(double(a[c]) - double(b[c])));
    return d;
}

// NaN against anything (a NaN in either file) is the largest difference there is.
double safeDifference(double d) {
    return std::isnan(d) ? HUGE_VAL : d;
}

void keepWorst(std::vector<VoxelDifference>& worst, const VoxelDifference& v) {
    const auto larger = [](const VoxelDifference& a, const VoxelDifference& b) {
        if (a.difference != b.difference) return a.difference > b.difference;
        return std::tie(a.ijk.x, a.ijk.y, a.ijk.z) < std::tie(b.ijk.x, b.ijk.y, b.ijk.z);
    };
    if (int(worst.size()) == kWorstVoxels && !larger(v, worst.back())) return;
    worst.insert(std::upper_bound(worst.begin(), worst.end(), v, larger), v);
    if (int(worst.size()) > kWorstVoxels) worst.pop_back();
}

template <typename GridT>
GridDifference compareGrids(const GridT& test, const GridT& reference, double tolerance) {
    GridDifference out;
    auto testAcc = test.getConstAccessor();
    auto refAcc = reference.getConstAccessor();
    const auto visit = [&](const Coord& c) {
        const auto r = refAcc.getValue(c);
        const auto t = testAcc.getValue(c);
        const double d = safeDifference(difference(t, r));
        ++out.voxelsCompared;
        if (d > tolerance) ++out.voxelsOver;
        out.maxDifference = std::max(out.maxDifference, d);
        if (d > 0.0) keepWorst(out.worst, {{c.x(), c.y(), c.z()}, magnitude(r), magnitude(t), d});
    };
    // Every voxel active in the reference (tiles voxel by voxel), then those active only in the
    // new grid.
    const auto eachActive = [](const GridT& grid, auto&& f) {
        for (auto it = grid.cbeginValueOn(); it; ++it) {
            if (it.isVoxelValue()) {
                f(it.getCoord());
                continue;
            }
            const openvdb::CoordBBox box = it.getBoundingBox();
            for (auto c = box.begin(); c; ++c) f(*c);
        }
    };
    eachActive(reference, visit);
    eachActive(test, [&](const Coord& c) {
        if (!refAcc.isValueOn(c)) visit(c);
    });
    return out;
}

template <typename GridT>
bool compareAs(const openvdb::GridBase& test, const openvdb::GridBase& reference, double tolerance,
               GridDifference& out) {
    const auto* t = dynamic_cast<const GridT*>(&test);
    const auto* r = dynamic_cast<const GridT*>(&reference);
    if (!t || !r) return false;
    const std::string name = out.name, type = out.type;
    out = compareGrids(*t, *r, tolerance);
    out.name = name;
    out.type = type;
    return true;
}

}  // namespace

bool VdbFileDifference::within() const {
    if (!problems.empty()) return false;
    for (const GridDifference& g : grids)
        if (g.voxelsOver > 0) return false;
    return true;
}

VdbFileDifference compareVdbFiles(const std::string& testPath, const std::string& referencePath,
                                  double tolerance, const std::vector<std::string>& gridNames) {
    VdbReader reference(referencePath);
    VdbReader test(testPath);
    std::map<std::string, size_t> testIndex;
    for (size_t i = 0; i < test.entries().size(); ++i) testIndex.emplace(test.entries()[i].name, i);
    VdbFileDifference out;
    std::vector<std::string> wanted = gridNames;
    if (wanted.empty())
        for (const VdbReader::Entry& e : reference.entries()) wanted.push_back(e.name);
    for (const std::string& name : wanted) {
        size_t r = reference.entries().size();
        for (size_t i = 0; i < reference.entries().size(); ++i)
            if (reference.entries()[i].name == name) r = i;
        if (r == reference.entries().size()) {
            out.problems.push_back("grid '" + name + "' is not in the reference");
            continue;
        }
        const auto t = testIndex.find(name);
        if (t == testIndex.end()) {
            out.problems.push_back("grid '" + name + "' is missing from the new file");
            continue;
        }
        const std::string& refType = reference.entries()[r].type;
        const std::string& testType = test.entries()[t->second].type;
        if (refType != testType) {
            out.problems.push_back("grid '" + name + "' is " + testType + ", the reference's " +
                                   refType);
            continue;
        }
        const openvdb::GridBase::Ptr refGrid = reference.readGrid(r);
        const openvdb::GridBase::Ptr testGrid = test.readGrid(t->second);
        GridDifference g;
        g.name = name;
        g.type = refType;
        if (!compareAs<openvdb::FloatGrid>(*testGrid, *refGrid, tolerance, g) &&
            !compareAs<openvdb::DoubleGrid>(*testGrid, *refGrid, tolerance, g) &&
            !compareAs<openvdb::Vec3SGrid>(*testGrid, *refGrid, tolerance, g)) {
            out.problems.push_back("grid '" + name + "' is of type " + refType +
                                   ", which is compared by hash only");
            continue;
        }
        out.grids.push_back(std::move(g));
    }
    return out;
}

}  // namespace eikon
