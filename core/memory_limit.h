#pragma once
// The most memory eikon lets one piece of work plan to take, and the check made before
// allocating it. Running out is not an error eikon can report: a failed allocation deep inside
// OpenVDB or TBB may throw again while unwinding (OpenVDB's Tree destructor allocates its
// tasks), which ends the process with SIGABRT instead of a message. So every allocation whose
// size the input decides (a procedural field's voxels, the render volume, the image, a smoke
// domain, a VDB grid's leaves, a photon budget) is estimated first and refused above the limit,
// with the JSON pointer or the file that asked for it.
//
// The limit (docs/scene-format.md, "Memory"): 3/4 of the memory this process may use, which is
// the machine's physical memory, or less where a cgroup (memory.max) or an address-space limit
// (ulimit -v) says so. EIKON_MEMORY_LIMIT in the environment or --memory-limit on the command
// line replaces it ("512M", "8G", "1.5GiB", or bytes).
#include <cstdint>
#include <optional>
#include <string>

namespace eikon {

struct MemoryLimit {
    double bytes = 0.0;
    std::string origin;  // where it came from, for messages: "--memory-limit", ...
};

// The limit in force: the one set by setMemoryLimit, else EIKON_MEMORY_LIMIT, else the default.
// Throws eikon::Error when EIKON_MEMORY_LIMIT is not a size.
MemoryLimit memoryLimit();
// Replaces the limit for the rest of the process (the command line's --memory-limit).
void setMemoryLimit(double bytes, const std::string& origin);
// Forgets setMemoryLimit's: the environment or the default applies again (tests).
void resetMemoryLimit();

// "512M", "8G", "8GiB", "1.5T", "4096" (bytes): units are binary (K = 1024); nullopt when
// `text` is not a positive size.
std::optional<double> parseByteSize(const std::string& text);
// "1.5 GiB", "512 MiB", "12 KiB", "100 B".
std::string formatBytes(double bytes);

// Throws eikon::Error(where, ...) when `bytes` exceeds the limit: "<what> needs about X, over
// eikon's memory limit of Y (<origin>); <advice>, or raise the limit with --memory-limit or
// EIKON_MEMORY_LIMIT". `advice` says what in the input to change ("use a larger voxel_size").
void checkMemory(const std::string& where, double bytes, const std::string& what,
                 const std::string& advice);

// Estimates, each an upper bound of what the allocation takes, measured by peak RSS at two sizes
// (scripts/measure-memory.sh, run as the memory_estimates test, checks each is an upper bound
// and not more than 4 times the measured slope).
//
// Render volume: the dense copies of the fields, ∇n, the octree, the fluence and the GPU
// textures (which live in host memory on llvmpipe), with one volume of particle deposits, and
// the CPU twins' constant bricks (render/constant_bricks.h: at most 2.8 B a voxel).
// Measured 118 B per voxel.
constexpr double kRenderBytesPerVoxel = 160.0;
// The CPU particle traces' deposits: 6 int64 sums a voxel in each tracing thread's own volume
// (render/transport/photons/deposit_buffers_cpu.h). kRenderBytesPerVoxel counts one; the other
// threads' take at most kThreadDepositBudget together (past it, threads share atomics).
constexpr double kDepositBytesPerVoxel = 48.0;
constexpr double kThreadDepositBudget = 1073741824.0;  // 1 GiB
// The render volume of `voxels`: kRenderBytesPerVoxel each, and the deposit volumes of this
// process's threads (TBB's concurrency) beyond the first.
double renderVolumeBytes(double voxels);
// Image: radiance, transmittance, tone-mapped copies. Measured 19 B per pixel.
constexpr double kRenderBytesPerPixel = 32.0;
// Smoke solver: the MAC velocity and its copies, density, temperature, pressure, the
// conjugate-gradient vectors, the frame written out. Measured 41 B per cell.
constexpr double kSmokeBytesPerCell = 64.0;
// A photon: its GPU record (48 B), round list, extinction and the copy read back.
constexpr double kPhotonBytes = 128.0;
// OpenVDB grids: counted node by node (VdbTreeNodeCounts::bytes, core/vdb_grid_check.h).

}  // namespace eikon
