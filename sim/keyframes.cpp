#include "sim/keyframes.h"

#include <algorithm>
#include <cmath>

namespace eikon::sim {

namespace {

// Key k's value, and (CubicSpline) its in- and out-tangents, component c.
struct Keys {
    const AnimationTrack& track;
    bool cubic() const { return track.interpolation == Interpolation::CubicSpline; }
    size_t stride() const { return size_t(track.width) * (cubic() ? 3 : 1); }
    double value(size_t k, int c) const {
        return track.values[k * stride() + (cubic() ? size_t(track.width) : 0) + size_t(c)];
    }
    double inTangent(size_t k, int c) const { return track.values[k * stride() + size_t(c)]; }
    double outTangent(size_t k, int c) const {
        return track.values[k * stride() + 2 * size_t(track.width) + size_t(c)];
    }
};

// Catmull-Rom's tangent at key k (per second): the slope between its neighbours, one-sided at
// the ends.
double catmullRomTangent(const Keys& keys, size_t k, int c) {
    const std::vector<double>& t = keys.track.times;
    const size_t lo = k == 0 ? 0 : k - 1;
    const size_t hi = std::min(k + 1, t.size() - 1);
    return (keys.value(hi, c) - keys.value(lo, c)) / (t[hi] - t[lo]);
}

void normalize(int width, double* v) {
    double length2 = 0.0;
    for (int c = 0; c < width; ++c) length2 += v[c] * v[c];
    const double length = std::sqrt(length2);
    if (length > 0.0)
        for (int c = 0; c < width; ++c) v[c] /= length;
}

}  // namespace

void evaluateTrack(const AnimationTrack& track, bool rotation, double seconds, float* out) {
    const Keys keys{track};
    const std::vector<double>& t = track.times;
    const int w = track.width;
    double v[4] = {0.0, 0.0, 0.0, 0.0};
    auto hold = [&](size_t k) {
        for (int c = 0; c < w; ++c) out[c] = float(keys.value(k, c));
    };
    if (!(seconds > t.front()) || t.size() == 1) return hold(0);  // NaN too: the first key
    if (seconds >= t.back()) return hold(t.size() - 1);
    const size_t k = size_t(std::upper_bound(t.begin(), t.end(), seconds) - t.begin()) - 1;
    const double span = t[k + 1] - t[k];
    const double u = (seconds - t[k]) / span;

    switch (track.interpolation) {
        case Interpolation::Step:
            return hold(k);
        case Interpolation::Linear:
            if (rotation) {
                // Slerp along the shorter arc: q and −q are the same rotation.
                double dot = 0.0;
                for (int c = 0; c < 4; ++c) dot += keys.value(k, c) * keys.value(k + 1, c);
                const double sign = dot < 0.0 ? -1.0 : 1.0;
                dot = std::min(1.0, std::abs(dot));
                const double angle = std::acos(dot);
                double a = 1.0 - u, b = u;  // nearly equal keys: linear, then normalized
                if (angle > 1e-6) {
                    a = std::sin((1.0 - u) * angle) / std::sin(angle);
                    b = std::sin(u * angle) / std::sin(angle);
                }
                for (int c = 0; c < 4; ++c)
                    v[c] = a * keys.value(k, c) + sign * b * keys.value(k + 1, c);
            } else {
                for (int c = 0; c < w; ++c)
                    v[c] = (1.0 - u) * keys.value(k, c) + u * keys.value(k + 1, c);
            }
            break;
        case Interpolation::CatmullRom:
        case Interpolation::CubicSpline: {
            // Cubic Hermite on [t_k, t_k+1] with tangents per second, scaled by the span.
            const double u2 = u * u, u3 = u2 * u;
            const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u;
            const double h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
            const bool cubic = track.interpolation == Interpolation::CubicSpline;
            for (int c = 0; c < w; ++c) {
                const double m0 = cubic ? keys.outTangent(k, c) : catmullRomTangent(keys, k, c);
                const double m1 =
                    cubic ? keys.inTangent(k + 1, c) : catmullRomTangent(keys, k + 1, c);
                v[c] = h00 * keys.value(k, c) + h10 * span * m0 + h01 * keys.value(k + 1, c) +
                       h11 * span * m1;
            }
            break;
        }
    }
    if (rotation) normalize(w, v);
    for (int c = 0; c < w; ++c) out[c] = float(v[c]);
}

}  // namespace eikon::sim
