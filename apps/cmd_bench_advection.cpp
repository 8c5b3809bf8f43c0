// `eikon bench advection`: speed against error for every advection scheme and limiter on the
// problems the tests check (sim/advection_problems.h): Zalesak's slotted sphere turned once and
// Enright's deformation, at two or more resolutions. Writes a table, and a TSV that
// scripts/plot_advection_bench.py turns into a PNG. With --peer openvdb, OpenVDB's
// tools::VolumeAdvection runs the same problems in the same run (sim/openvdb_advection_peer.h)
// and the table ends with the ratios of matching schemes.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "apps/bench_report.h"
#include "apps/commands.h"
#include "core/error.h"
#include "sim/advection_problems.h"
#include "sim/openvdb_advection_peer.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

struct BenchAdvectionOptions {
    std::string sizes = "32,64";
    std::string problems = "zalesak,enright";
    // A third of Enright's T = 3: at 32³-64³ his sheet gets thinner than a cell, semi-Lagrangian
    // then loses the whole sphere (L1 1.5, every cell below ½) and the table says little.
    // --period 3 runs the paper's.
    double period = 1.0;
    int threads = 0;
    bool quick = false;
    std::string tsv = "out/bench/advection.tsv";
    std::string peer = "none";  // or "openvdb"
};

// Each scheme with each limiter that matters: semi-Lagrangian blends stay in range by
// themselves, so a limiter would change nothing there.
const sim::AdvectionSettings kConfigs[] = {
    {sim::AdvectionScheme::SemiLagrangian, sim::Limiter::None},
    {sim::AdvectionScheme::MacCormack, sim::Limiter::Clamp},
    {sim::AdvectionScheme::MacCormack, sim::Limiter::Revert},
    {sim::AdvectionScheme::Bfecc, sim::Limiter::Clamp},
    {sim::AdvectionScheme::Bfecc, sim::Limiter::Revert},
};

// OpenVDB's schemes, each with its limiters (its limiter acts on MAC and BFECC only). MID is a
// midpoint back-trace, like our semi-Lagrangian; SEMI is OpenVDB's default, forward Euler.
struct PeerConfig {
    sim::VdbIntegrator integrator;
    sim::VdbLimiter limiter;
    // The Eikon configuration it is compared with in the ratios.
    sim::AdvectionSettings counterpart;
};
const PeerConfig kPeerConfigs[] = {
    {sim::VdbIntegrator::Semi,
     sim::VdbLimiter::None,
     {sim::AdvectionScheme::SemiLagrangian, sim::Limiter::None}},
    {sim::VdbIntegrator::Mid,
     sim::VdbLimiter::None,
     {sim::AdvectionScheme::SemiLagrangian, sim::Limiter::None}},
    {sim::VdbIntegrator::MacCormack,
     sim::VdbLimiter::Clamp,
     {sim::AdvectionScheme::MacCormack, sim::Limiter::Clamp}},
    {sim::VdbIntegrator::MacCormack,
     sim::VdbLimiter::Revert,
     {sim::AdvectionScheme::MacCormack, sim::Limiter::Revert}},
    {sim::VdbIntegrator::Bfecc,
     sim::VdbLimiter::Clamp,
     {sim::AdvectionScheme::Bfecc, sim::Limiter::Clamp}},
    {sim::VdbIntegrator::Bfecc,
     sim::VdbLimiter::Revert,
     {sim::AdvectionScheme::Bfecc, sim::Limiter::Revert}},
};

const char* limiterName(sim::VdbLimiter l) {
    switch (l) {
        case sim::VdbLimiter::None:
            return "none";
        case sim::VdbLimiter::Clamp:
            return "clamp";
        case sim::VdbLimiter::Revert:
            return "revert";
    }
    return "?";
}

const char* limiterName(sim::Limiter l) {
    switch (l) {
        case sim::Limiter::None:
            return "none";
        case sim::Limiter::Clamp:
            return "clamp";
        case sim::Limiter::Revert:
            return "revert";
    }
    return "?";
}

struct Problem {
    std::string name;
    std::string description;
};

std::vector<Problem> parseProblems(const std::string& text, double period) {
    std::vector<Problem> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        if (item == "zalesak")
            out.push_back({item, "Zalesak's slotted sphere (Enright's 3D set-up), one turn, n^3"});
        else if (item == "zalesak-disk")
            out.push_back({item, "Zalesak's slotted disk, one turn, n x n x 2 slab (the tests')"});
        else if (item == "enright") {
            char text[96];
            std::snprintf(text, sizeof text,
                          "Enright's deformation of a sphere r 0.15, period T = %g s, n^3", period);
            out.push_back({item, text});
        } else
            throw Error("--problems", "unknown problem '" + item +
                                          "' (expected zalesak, zalesak-disk or enright)");
    }
    if (out.empty()) throw Error("--problems", "expected at least one problem");
    return out;
}

sim::AdvectionProblemResult runProblem(const std::string& name, int n,
                                       sim::DensityAdvector& advector, double period) {
    if (name == "zalesak") return sim::zalesakRotation(n, sim::ZalesakShape::Sphere, advector);
    if (name == "zalesak-disk") return sim::zalesakRotation(n, sim::ZalesakShape::Disk, advector);
    return sim::enrightDeformation(n, advector, period);
}

sim::AdvectionProblemResult runProblem(const std::string& name, int n,
                                       const sim::AdvectionSettings& s, double period) {
    if (name == "zalesak") return sim::zalesakRotation(n, sim::ZalesakShape::Sphere, s);
    if (name == "zalesak-disk") return sim::zalesakRotation(n, sim::ZalesakShape::Disk, s);
    return sim::enrightDeformation(n, s, period);
}

// One row of the table and the TSV.
struct Row {
    std::string problem, scheme, limiter;
    int n = 0;
    long cells = 0;
    sim::AdvectionProblemResult result;
    double msPerStep() const { return result.advectionMs / result.steps; }
};

int runBenchAdvection(BenchAdvectionOptions o) {
    if (o.quick) o.sizes = "12,16";
    if (!(o.period > 0.0)) throw Error("--period", "must be positive");
    const std::vector<int> sizes = parseSizeList(o.sizes, "--sizes");
    const std::vector<Problem> problems = parseProblems(o.problems, o.period);
    const auto threadCap = limitThreads(o.threads);
    if (o.peer != "none" && o.peer != "openvdb")
        throw Error("--peer", "unknown peer '" + o.peer + "' (expected none or openvdb)");
    const bool peer = o.peer == "openvdb";

    std::printf("# eikon bench advection: L1 error against ms per step, per scheme\n");
    printBenchHeader(stdout, o.threads);
    for (const Problem& p : problems)
        std::printf("# problem %s: %s\n", p.name.c_str(), p.description.c_str());
    std::printf(
        "# CFL 1; a sharp 0/1 indicator in a closed unit box, advected with advectField() "
        "alone; ms per step times that call only\n");
    std::printf("# L1 = sum|phi - phi0| / sum phi0 at the end (the exact answer is phi0)\n");
    if (peer)
        std::printf(
            "# peer: OpenVDB %s tools::VolumeAdvection, staggered velocity, trilinear sampler, "
            "sparse density masked to the box; ms per step times its advect() call only\n",
            sim::openVdbVersion());

    if (fs::path(o.tsv).has_parent_path()) fs::create_directories(fs::path(o.tsv).parent_path());
    std::ofstream tsv(o.tsv);
    if (!tsv) throw Error(o.tsv, "cannot write the TSV file");
    tsv << "problem\tscheme\tlimiter\tresolution\tcells\tsteps\tms_per_step\tl1\tvolume_loss\t"
           "mass_change\n";

    std::printf("%-13s %-16s %-7s %5s %10s %6s | %10s | %9s %11s %11s\n", "problem", "scheme",
                "limiter", "n", "cells", "steps", "ms/step", "L1", "volume loss", "mass change");
    auto emit = [&](const Row& row) {
        const sim::AdvectionProblemResult& r = row.result;
        std::printf("%-13s %-16s %-7s %5d %10ld %6d | %10.3f | %9.4f %11.4f %11.4f\n",
                    row.problem.c_str(), row.scheme.c_str(), row.limiter.c_str(), row.n, row.cells,
                    r.steps, row.msPerStep(), r.l1, r.volumeLoss, r.massChange);
        std::fflush(stdout);
        tsv << row.problem << '\t' << row.scheme << '\t' << row.limiter << '\t' << row.n << '\t'
            << row.cells << '\t' << r.steps << '\t' << row.msPerStep() << '\t' << r.l1 << '\t'
            << r.volumeLoss << '\t' << r.massChange << '\n';
    };
    // Ours and the peer's, interleaved per problem and size so that both see the same machine.
    struct Pair {
        const Row* ours;
        const Row* peer;
    };
    std::vector<Row> rows;
    rows.reserve(problems.size() * sizes.size() * (std::size(kConfigs) + std::size(kPeerConfigs)));
    std::vector<Pair> pairs;
    for (const Problem& p : problems)
        for (int n : sizes) {
            const long cells = long(n) * n * (p.name == "zalesak-disk" ? 2 : n);
            const std::size_t first = rows.size();
            for (const sim::AdvectionSettings& s : kConfigs) {
                rows.push_back({p.name, sim::schemeName(s.scheme), limiterName(s.limiter), n, cells,
                                runProblem(p.name, n, s, o.period)});
                emit(rows.back());
            }
            if (!peer) continue;
            for (const PeerConfig& c : kPeerConfigs) {
                auto advector = sim::makeOpenVdbAdvector(c.integrator, c.limiter);
                rows.push_back(
                    {p.name, std::string("OpenVDB ") + sim::vdbIntegratorName(c.integrator),
                     limiterName(c.limiter), n, cells, runProblem(p.name, n, *advector, o.period)});
                emit(rows.back());
                for (std::size_t k = 0; k < std::size(kConfigs); ++k)
                    if (kConfigs[k].scheme == c.counterpart.scheme &&
                        kConfigs[k].limiter == c.counterpart.limiter)
                        pairs.push_back({&rows[first + k], &rows.back()});
            }
        }
    if (peer) {
        std::printf(
            "# against OpenVDB tools::VolumeAdvection: ms/step and L1 of each, ratio "
            "OpenVDB / Eikon\n");
        std::printf("%-13s %5s %-26s %-22s | %9s %9s %7s | %7s %7s\n", "problem", "n", "Eikon",
                    "OpenVDB", "Eikon ms", "VDB ms", "ratio", "Eikon L1", "VDB L1");
        for (const Pair& q : pairs)
            std::printf("%-13s %5d %-26s %-22s | %9.3f %9.3f %7.2f | %7.4f %7.4f\n",
                        q.ours->problem.c_str(), q.ours->n,
                        (q.ours->scheme + " + " + q.ours->limiter).c_str(),
                        (q.peer->scheme + " + " + q.peer->limiter).c_str(), q.ours->msPerStep(),
                        q.peer->msPerStep(), q.peer->msPerStep() / q.ours->msPerStep(),
                        q.ours->result.l1, q.peer->result.l1);
    }
    std::printf("# wrote %s (plot: /usr/bin/python3 scripts/plot_advection_bench.py %s)\n",
                o.tsv.c_str(), o.tsv.c_str());
    return 0;
}

}  // namespace

void addBenchAdvectionCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "advection", "Speed against error of each advection scheme on Zalesak and Enright tests");
    auto o = std::make_shared<BenchAdvectionOptions>();
    cmd->add_option("--sizes", o->sizes, "resolutions n, comma-separated (default 32,64)");
    cmd->add_option("--problems", o->problems,
                    "comma-separated: zalesak, zalesak-disk, enright (default zalesak,enright)");
    cmd->add_option("--period", o->period,
                    "Enright's period T in seconds (default 1; the paper's is 3)");
    cmd->add_option("--threads", o->threads, "cap TBB's threads (default: all cores)");
    cmd->add_flag("--quick", o->quick, "smallest run, to check that it works: n = 12 and 16");
    cmd->add_option("--tsv", o->tsv, "TSV output (default out/bench/advection.tsv)");
    cmd->add_option("--peer", o->peer,
                    "openvdb: also run OpenVDB's tools::VolumeAdvection on the same problems "
                    "(default none)");
    cmd->callback([o, &exitCode] { exitCode = runBenchAdvection(*o); });
}

}  // namespace eikon::app
