#pragma once
// The scene the CLI tests drag by ARAP handles: an emissive ball held at its base, its top a
// sphere handle, seen level from 3 units away with a 40° horizontal field.
#include <string>

namespace eikon::test {

// `extra`: more top-level keys, each with its leading comma.
inline std::string arapBallScene(int width, int height, const std::string& extra = "") {
    return R"({
  "volume": {"bounds": {"min": [-1, -1, -1], "max": [1, 1, 1]}, "resolution": 16},
  "meshes": [{"name": "ball", "shape": {"type": "icosphere", "radius": 0.5, "subdivisions": 2},
              "emission": [1, 0.6, 0.3], "absorption": [2, 2, 2],
              "deformer": {"type": "arap", "handles": [
                {"name": "base", "box": {"min": [-1, -1, -1], "max": [1, -0.3, 1]}},
                {"name": "top", "sphere": {"center": [0, 0.5, 0], "radius": 0.2}}]}}],
  "camera": {"position": [0, 0, 3], "look_at": [0, 0, 0], "horizontal_fov_deg": 40},
  "render": {"width": )" +
           std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(},
  "output": {"name": "ball", "png": true})" +
           extra + "\n}";
}

}  // namespace eikon::test
