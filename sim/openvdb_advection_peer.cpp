#include "sim/openvdb_advection_peer.h"

#include <memory>

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/VolumeAdvect.h>

namespace eikon::sim {
namespace {

namespace Scheme = openvdb::tools::Scheme;

Scheme::SemiLagrangian toVdb(VdbIntegrator i) {
    switch (i) {
        case VdbIntegrator::Semi:
            return Scheme::SEMI;
        case VdbIntegrator::Mid:
            return Scheme::MID;
        case VdbIntegrator::MacCormack:
            return Scheme::MAC;
        case VdbIntegrator::Bfecc:
            return Scheme::BFECC;
    }
    return Scheme::SEMI;
}

Scheme::Limiter toVdb(VdbLimiter l) {
    switch (l) {
        case VdbLimiter::None:
            return Scheme::NO_LIMITER;
        case VdbLimiter::Clamp:
            return Scheme::CLAMP;
        case VdbLimiter::Revert:
            return Scheme::REVERT;
    }
    return Scheme::NO_LIMITER;
}

class OpenVdbAdvector : public DensityAdvector {
public:
    OpenVdbAdvector(VdbIntegrator integrator, VdbLimiter limiter)
        : integrator_(integrator), limiter_(limiter) {
        openvdb::initialize();  // idempotent
    }

    void load(const MacGrid& g) override {
        transform_ = openvdb::math::Transform::createLinearTransform(g.domain.voxelSize);
        const glm::ivec3 n = g.resolution();
        density_ = openvdb::FloatGrid::create(0.0f);
        density_->setTransform(transform_);
        auto acc = density_->getAccessor();
        for (int k = 0; k < n.z; ++k)
            for (int j = 0; j < n.y; ++j)
                for (int i = 0; i < n.x; ++i)
                    if (const float v = g.density(i, j, k); v != 0.0f)
                        acc.setValue(openvdb::Coord(i, j, k), v);
        box_ = openvdb::BoolGrid::create(false);
        box_->setTransform(transform_);
        box_->tree().fill(
            openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(n.x - 1, n.y - 1, n.z - 1)), true,
            true);
    }

    void setVelocity(const MacGrid& g) override {
        advection_.reset();  // it refers to the old velocity grid
        velocity_ = openvdb::Vec3fGrid::create(openvdb::Vec3f(0.0f));
        velocity_->setTransform(transform_);
        velocity_->setGridClass(openvdb::GRID_STAGGERED);
        auto acc = velocity_->getAccessor();
        const glm::ivec3 n = g.resolution();
        for (int k = 0; k <= n.z; ++k)
            for (int j = 0; j <= n.y; ++j)
                for (int i = 0; i <= n.x; ++i) {
                    openvdb::Vec3f v(0.0f);
                    for (int a = 0; a < 3; ++a) {
                        const Array3& face = g.velocity[std::size_t(a)];
                        const glm::ivec3 s = face.size();
                        if (i < s.x && j < s.y && k < s.z) v[a] = face(i, j, k);
                    }
                    acc.setValue(openvdb::Coord(i, j, k), v);
                }
        // Made here, untimed: its constructor scans the velocity for its maximum, work that our
        // advectField() does not do and that a caller with a steady flow would do once.
        advection_ = std::make_unique<Advection>(*velocity_);
        advection_->setIntegrator(toVdb(integrator_));
        advection_->setLimiter(toVdb(limiter_));
    }

    void advect(MacGrid&, float dt) override {
        density_ = advection_->advect<openvdb::FloatGrid, openvdb::BoolGrid,
                                      openvdb::tools::Sampler<1, false>>(*density_, *box_, dt);
    }

    void store(MacGrid& g) override {
        const glm::ivec3 n = g.resolution();
        auto acc = density_->getConstAccessor();
        for (int k = 0; k < n.z; ++k)
            for (int j = 0; j < n.y; ++j)
                for (int i = 0; i < n.x; ++i)
                    g.density(i, j, k) = acc.getValue(openvdb::Coord(i, j, k));
    }

private:
    VdbIntegrator integrator_;
    VdbLimiter limiter_;
    openvdb::math::Transform::Ptr transform_;
    openvdb::FloatGrid::Ptr density_;
    openvdb::Vec3fGrid::Ptr velocity_;
    openvdb::BoolGrid::Ptr box_;
    using Advection = openvdb::tools::VolumeAdvection<openvdb::Vec3fGrid, /*staggered*/ true>;
    std::unique_ptr<Advection> advection_;
};

}  // namespace

const char* vdbIntegratorName(VdbIntegrator integrator) {
    switch (integrator) {
        case VdbIntegrator::Semi:
            return "SEMI";
        case VdbIntegrator::Mid:
            return "MID";
        case VdbIntegrator::MacCormack:
            return "MAC";
        case VdbIntegrator::Bfecc:
            return "BFECC";
    }
    return "?";
}

const char* openVdbVersion() {
    return openvdb::getLibraryVersionString();
}

std::unique_ptr<DensityAdvector> makeOpenVdbAdvector(VdbIntegrator integrator, VdbLimiter limiter) {
    return std::make_unique<OpenVdbAdvector>(integrator, limiter);
}

}  // namespace eikon::sim
