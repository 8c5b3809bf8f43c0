#pragma once
// The scene model: what to load, how fields become optics, lights, camera, output and time.
// Parsed strictly from JSON (see docs/scene-format.md): an unknown key, a wrong type or an
// out-of-range value is an eikon::Error whose where() is "<file>:<JSON pointer>", for example
// "smoke.json:/lights/0/intensity". Relative file paths are resolved against the scene's folder.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/bounds.h"
#include "core/dispersion.h"
#include "core/ray_integrator.h"
#include "core/simulation_spec.h"

namespace eikon {

struct VolumeSettings {
    // "bounds": "auto" (the union of the world bounds of every field a material reads) or
    // {"min": [x,y,z], "max": [x,y,z]} in scene units.
    bool autoBounds = true;
    Bounds3 bounds;
    // "resolution": "auto" (the voxel size of the first field a material reads, at most
    // max_resolution voxels along any axis) or [nx, ny, nz] or one integer for a cube.
    bool autoResolution = true;
    glm::ivec3 resolution{64, 64, 64};
    int maxResolution = 256;
};

// Simulation: the fields of the scene's own smoke simulation (density, temperature, velocity),
// stepped live frame by frame by the program rendering the scene (pipeline/scene_driver.h) instead
// of read from a cache; the scene must have a "simulation" section.
// Scan: a scanned volume (CT, MRI) in an NRRD file or a headerless raw file (core/scan_layout.h),
// read into field `field`.
enum class SourceType { Vdb, VdbSequence, Sphere, Box, Simulation, Scan };

// How a procedural shape's value varies inside it (core/procedural.h has the formulas).
// Uniform: `value` everywhere. Luneburg (spheres): value · (sqrt(2 − (r/R)²) − 1), so that a
// material of ior 2 reading it with value 1 gives the Luneburg lens n(r) = sqrt(2 − (r/R)²).
// Ramp: linear along an axis, from rampFrom at the shape's lowest extent to rampTo at its highest.
enum class SourceProfile { Uniform, Luneburg, Ramp };

// How a procedural shape's edge is averaged into its voxels (core/procedural.h, edgeWeight):
// Box, across the voxel's width (its coverage); BSpline, with the cubic B-spline over four voxels
// (core/bspline_edge.h). ShapeDefault: BSpline for spheres, whose surface crosses the grid at
// every angle and whose box-averaged edge aliases into rings in a caustic; Box for boxes, whose
// faces are the grid's planes and whose coverage is exact there.
enum class EdgeFilter { ShapeDefault, Box, BSpline };

struct SourceSpec {
    SourceType type = SourceType::Vdb;
    // Vdb: a file. VdbSequence: any frame of the sequence or a pattern with #### in it.
    std::string file;
    // Extra grid names per canonical field, tried before the built-in aliases,
    // e.g. {"density": ["soot_fine"]}.
    std::map<std::string, std::vector<std::string>> aliases;
    // VdbSequence: a frame rendered that the sequence lacks, between its first and last or
    // outside them, is an error, unless the scene says "missing_frames": "hold" (or `--hold` on
    // the command line): the nearest earlier frame shows, or the first before the first.
    bool holdMissingFrames = false;
    // Procedural shapes (Sphere, Box) write `value` (shaped by `profile`) into field `field`,
    // with a linear ramp of width `falloff` (scene units) outside the surface, on a grid of voxel
    // size `voxelSize`.
    std::string field = "density";
    glm::vec3 center{0.0f};     // Sphere
    float radius = 1.0f;        // Sphere
    glm::vec3 boxMin{-0.5f};    // Box
    glm::vec3 boxMax{0.5f};     // Box
    float cornerRadius = 0.0f;  // Box: edges and corners rounded to this radius
    float value = 1.0f;
    float falloff = 0.0f;
    EdgeFilter edgeFilter = EdgeFilter::ShapeDefault;
    float voxelSize = 0.05f;
    SourceProfile profile = SourceProfile::Uniform;
    int rampAxis = 1;  // Ramp: 0, 1, 2 for x, y, z
    float rampFrom = 0.0f;
    float rampTo = 0.0f;
    // The shape is kept only where a voxel centre lies in [clip.min, clip.max) (half-open, so
    // that shapes clipped to adjacent boxes share no voxel), with no falloff across the clip.
    std::optional<Bounds3> clip;
    // Scan: a headerless raw file's dimensions, value type ("uint8", "int16", ...) and byte order
    // (from its name `<name>_<X>x<Y>x<Z>_<type>.raw` when not given; an NRRD header says them
    // itself); the spacing and the position of sample (0, 0, 0), replacing the header's; the
    // window [low, high] that maps the stored values to [0, 1].
    std::optional<glm::ivec3> scanDims;
    std::string scanValueType;
    bool scanBigEndian = false;
    std::optional<glm::vec3> scanSpacing;
    std::optional<glm::vec3> scanOrigin;
    std::optional<glm::vec2> scanWindow;
    std::string jsonPath;  // e.g. "/sources/2", for messages raised after parsing
};

// A material's particle colour (core/particle_color.h): a colour map by name over a range of its
// field's values, or a piecewise-linear function through (value, r, g, b) points.
struct ParticleColorSpec {
    std::string map;                // a colour map by name (colorMapNames()); or empty, and:
    std::vector<glm::vec4> points;  // (value, r, g, b), values increasing, linear colours
    glm::vec2 range{0.0f, 1.0f};    // with `map`: the values its low and high ends stand for
    bool empty() const { return map.empty() && points.empty(); }
};

// One material maps one scalar field f to optics, linearly per unit of f:
// absorption α = f·absorption, scattering σ = f·scattering (extinction κ = σ + α, per scene unit),
// emission = f·emission (radiance per scene unit), refractive index n = 1 + f·(ior − 1) (except
// Gladstone–Dale air, below).
// The optics of several materials add up.
struct MaterialSpec {
    std::string name;
    std::string field = "density";
    glm::vec3 absorption{0.0f};
    glm::vec3 scattering{0.0f};
    float g = 0.0f;  // Henyey–Greenstein anisotropy, in (−1, 1)
    glm::vec3 emission{0.0f};
    // ≥ 1 as a scene gives it; ≠ 1 bends the view rays (render/refraction_volume.h). Below 1 when
    // the parser derives it from gladstoneDale.
    float ior = 1.0f;
    // Hot air (Gladstone–Dale at constant pressure: n − 1 ∝ gas density ∝ 1/T). When > 0, the
    // field f is the temperature excess T − T_ambient in kelvin and gladstoneDale is n − 1 of the
    // air at ambientKelvin; n is taken relative to that air (n = 1 at ambient), exactly:
    // n = 1 + gladstoneDale·(T_ambient/(T_ambient + f) − 1) = 1 − gladstoneDale·f/(T_ambient + f)
    // (shaders/shared/material_index.h, per voxel on the GPU and the CPU twin). The parser sets
    // ior = 1 − gladstoneDale/ambientKelvin, the slope at ambient, which is what "does this
    // material refract" tests read; the map itself is not linear in f.
    float gladstoneDale = 0.0f;
    float ambientKelvin = 288.15f;
    // The edge of its field is a sharp surface (glass, water: a mesh's, or a field that steps from
    // 0 to 1 in a few voxels), where light crossing it is partly reflected by Fresnel's law
    // (shaders/shared/fresnel.h). False for an index graded over many wavelengths (a GRIN lens,
    // hot air), which reflects nothing however steep its gradient is on the grid. The parser
    // makes it false for Gladstone–Dale materials.
    bool fresnel = true;
    // The roughness of its sharp surfaces (with `fresnel`) for the lights' specular highlights
    // seen on them (shaders/shared/specular.h: Cook–Torrance with GGX, Magnus's thesis §4.3), in
    // (0, 1]; 0: none (a smooth surface mirrors a light to a point no pixel resolves).
    float roughness = 0.0f;
    // Dispersion (core/dispersion.h): ior is n_d, the green channel's index, and abbe the Abbe
    // number V_d that parts red and blue from it; 0: n the same in every channel.
    float abbe = 0.0f;
    // A transfer function (core/transfer_function.h): the material reads amount(f), piecewise
    // linear through these (value, amount) points, flat beyond the first and the last, in place
    // of f itself; applied to the field's values at the render volume's voxels (pre-classified).
    // Empty: the field's value itself (f ↦ f).
    std::vector<glm::vec2> transfer;
    // A particle colour (core/particle_color.h): what the material scatters and emits is tinted
    // by color(f), f its field's own value (before `transfer`); empty: no tint.
    ParticleColorSpec particleColor;

    // n in the red, green and blue channels (ior in each without dispersion).
    glm::vec3 channelIor() const { return channelIndices(ior, abbe); }
    // n − 1 per unit of the field at f = 0: ior − 1, or −gladstoneDale/ambientKelvin computed
    // directly (ior itself, a float next to 1, keeps only ~2 digits of a real air's 1e-6).
    float indexSlope() const {
        return gladstoneDale > 0.0f ? -gladstoneDale / ambientKelvin : ior - 1.0f;
    }
    // 1/T_ambient for a Gladstone–Dale material, 0 for a linear one: the one number that makes
    // shaders/shared/material_index.h exact for hot air.
    float inverseAmbient() const { return gladstoneDale > 0.0f ? 1.0f / ambientKelvin : 0.0f; }
};

// A closed triangle mesh voxelized into the render volume every frame it changes (Sun et al. 2008
// §4.1; render/voxelize.h), carrying its own material. Placed by scale, then rotation, then
// translation (glTF's TRS order). The parser turns its optics into ordinary materials over two
// fields of its own (meshMaterialFieldNames): its coverage for absorption, scattering and
// emission, and the coverage blurred by the Gaussian (σ, radius in voxels) for n, since only n
// needs to be smooth (its gradient is the surface normal). Overlapping meshes: a later mesh in
// the list displaces earlier ones (each coverage is multiplied by 1 − the coverage of every later
// mesh), so the optics never add up where two objects overlap.
// A liquid fills an earlier mesh (its container, a glass or cup) to a fraction of its cavity's
// depth (sim/container_fill.h), placed by the container's placement as that moves (placementOf).
// A LevelSet is a solid read from a VDB or NanoVDB file's signed distance (core/level_set.h): its
// coverage comes from the distance instead of from triangles; the blur, ∇n, placement and
// overlap rule are the meshes'.
enum class MeshShapeType { File, Icosphere, Box, Water, Liquid, LevelSet };

// Which grid of a VDB file a level set comes from: by name, by its index in the file (an unnamed
// grid has only that), or, with neither, the file's one grid of class "level set".
struct GridChoice {
    std::string name;
    int index = -1;
    bool given() const { return !name.empty() || index >= 0; }
};

// A pool of water whose surface follows the damped wave equation (sim/water_surface.h), stepped
// on the scene's clock; droplets dent it at given times.
struct WaterDropletSpec {
    double time = 0.0;         // seconds
    glm::vec2 position{0.0f};  // (x, z) in the pool's object space
    float radius = 0.05f;      // σ of the Gaussian dent, scene units
    float depth = 0.02f;       // how far the dent lowers the surface at its centre
};

struct WaterSpec {
    glm::vec2 size{2.0f, 2.0f};              // x and z extent, centred on the object's origin
    glm::ivec2 cells{64, 64};                // nx, nz
    float depth = 0.3f;                      // rest surface above the bottom (y = 0)
    float waveSpeed = 1.0f;                  // c, scene units per second
    float damping = 0.0f;                    // γ, per second
    std::vector<WaterDropletSpec> droplets;  // in any order
};

// A jelly deformer on a mesh (sim/jelly.h): a mass-spring body that keeps its volume, under
// gravity, on a floor, poked at given times; stepped on the scene's clock in world space.
struct JellyPokeSpec {
    double time = 0.0;
    glm::vec3 position{0.0f};  // world space
    float radius = 0.1f;       // vertices within this distance get the velocity, falling off
    glm::vec3 velocity{0.0f};  // added at the poke's centre (scene units per second)
};

struct JellySpec {
    float mass = 1.0f;               // the whole body's, spread evenly over the vertices
    float stiffness = 150.0f;        // edge springs: force per unit strain (k = this / length)
    float bendStiffness = 40.0f;     // springs across adjacent triangles
    float volumeStiffness = 300.0f;  // k_v
    float damping = 0.0f;            // velocity damping per second (0: none)
    glm::vec3 gravity{0.0f, -9.81f, 0.0f};
    std::optional<float> floorY;  // none: no floor
    float friction = 5.0f;        // per second, on the tangential velocity in contact
    // At least this many steps per frame; more when the springs' highest frequency needs them.
    int substeps = 40;
    std::vector<JellyPokeSpec> pokes;
};

// An as-rigid-as-possible deformer on a mesh (sim/arap_deformer.h, Sorkine & Alexa 2007): the
// vertices inside each handle's region (in the mesh's object space, before placement) move
// rigidly with the handle (about the region's centre: rotation, then translation), and the rest
// of the mesh follows as rigidly as it can. Handle motion comes from keyframe tracks
// (/meshes/<i>/deformer/handles/<j>/translate, .../rotation); a handle without any stays put.
struct ArapHandleSpec {
    std::string name;
    bool sphere = true;
    glm::vec3 center{0.0f};                // sphere; a box's centre is filled in as the pivot too
    float radius = 0.1f;                   // sphere
    glm::vec3 boxMin{0.0f}, boxMax{0.0f};  // box
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // w, x, y, z
};

struct ArapSpec {
    // Local/global iterations per frame, each frame starting from the previous frame's shape
    // (frame 0 from the rest shape), as an interactive drag would.
    int iterations = 5;
    std::vector<ArapHandleSpec> handles;
};

struct MeshObjectSpec {
    std::string name;  // unique among meshes and materials
    MeshShapeType shape = MeshShapeType::File;
    // File: OBJ, OFF, PLY or STL; LevelSet: VDB or NanoVDB. Resolved against the scene's folder.
    std::string file;
    GridChoice grid;          // LevelSet
    int closeHolesUpTo = 0;   // File: fill holes of up to this many edges (0: open meshes fail)
    float radius = 0.5f;      // Icosphere, around the object's origin
    int subdivisions = 4;     // Icosphere: 20·4^s triangles
    glm::vec3 boxMin{-0.5f};  // Box
    glm::vec3 boxMax{0.5f};   // Box
    WaterSpec water;          // Water
    int container = -1;       // Liquid: index of the mesh it fills, always an earlier one
    double fill = 0.5;        // Liquid: fraction of the cavity's depth, in (0, 1]
    std::optional<JellySpec> jelly;  // a deformer: the mesh wobbles as a jelly
    std::optional<ArapSpec> arap;    // a deformer: handles drag the mesh as rigidly as possible
    glm::vec3 scale{1.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // w, x, y, z
    glm::vec3 translation{0.0f};
    float blurSigmaVoxels = 1.5f;  // Sun et al.: σ = 1.5 voxels in a 9³ window
    int blurRadiusVoxels = 4;
    std::string jsonPath;  // e.g. "/meshes/0"
};

enum class LightType { Point, Directional, Spot };

struct LightSpec {
    LightType type = LightType::Directional;
    glm::vec3 position{0.0f};                // Point, Spot
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // Directional, Spot: the way the light travels
    glm::vec3 color{1.0f};
    // Directional: irradiance normal to the direction. Point, Spot: radiant intensity (per sr),
    // so irradiance falls off as intensity / r².
    float intensity = 1.0f;
    float coneAngleDeg = 30.0f;    // Spot: half-angle where the light ends
    float coneSoftnessDeg = 5.0f;  // Spot: width of the smooth edge inside the cone
    // Directional: the angle the light's disc subtends (the sun: 0.53°), which softens its
    // shadows and caustics; 0 is a single direction. kMaxAngularDiameterDeg at most.
    float angularDiameterDeg = 0.0f;
};

constexpr float kMaxAngularDiameterDeg = 30.0f;

struct CameraSpec {
    bool automatic = true;  // "camera": "auto" frames the render volume
    glm::vec3 position{0.0f, 0.0f, 5.0f};
    glm::vec3 lookAt{0.0f};
    // Automatic: the world axis that is up (+x, +y or +z), which also picks the side the camera
    // looks from (core/camera.h).
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    // Automatic: the box to frame, the same every frame; unset frames each frame's render volume.
    // The default scene of a VDB file or sequence sets it (core/default_scene.cpp).
    std::optional<Bounds3> framed;
    float horizontalFovDeg = 45.0f;  // in (0, 180)
};

// What view rays see where they leave the volume (shaders/shared/environment.h). Up is +y.
enum class EnvironmentType { Color, Gradient, Image };

struct EnvironmentSpec {
    EnvironmentType type = EnvironmentType::Color;
    glm::vec3 color{0.0f};  // Color: constant background radiance
    // Gradient: the sky blends horizon -> zenith by sqrt(sin(elevation)); below the horizon the
    // ground colour takes over within a short blend.
    glm::vec3 zenith{0.0f};
    glm::vec3 horizon{0.0f};
    glm::vec3 ground{0.0f};
    // Image: an equirectangular linear EXR (resolved against the scene's folder; read by
    // render/environment_map.h, since core does not read images), its radiance × intensity,
    // turned by rotationDeg about +y (counter-clockwise seen from above).
    std::string file;
    float intensity = 1.0f;
    float rotationDeg = 0.0f;
};

// A diffuse receiver (Sun et al. 2008 §5.5 floors and walls): an axis-aligned plane across the
// render volume, opaque from both sides, that shows the light reaching its front face (caustics
// and shadows). Photons stop on it; its front face (the side `facing` points to) reflects
// albedo/π × irradiance toward the camera, its back face is black. Method Plane gathers the flux
// of the photons crossing it into a map of `texelsPerVoxel` texels per voxel edge (sharp);
// Voxels reads the photon volumes beside it, as Sun et al.'s voxel floors do (blurred by the
// volume's resolution and smoothing). Lights that reach the medium straight (no photons) light
// it through their light volumes either way.
enum class ReceiverMethod { Plane, Voxels };

struct ReceiverSpec {
    int axis = 1;            // 0 = x, 1 = y, 2 = z: the plane's normal axis
    float position = 0.0f;   // the plane's coordinate on that axis, inside the render volume
    int facing = 1;          // +1: the front faces +axis; −1: −axis
    glm::vec3 albedo{0.8f};  // diffuse reflectance per channel, in [0, 1]
    ReceiverMethod method = ReceiverMethod::Plane;
    int texelsPerVoxel = 2;  // Plane: map texels along each voxel edge
    std::string jsonPath;    // e.g. "/receivers/0", for messages raised after parsing
};

// A clipping plane (Magnus's thesis, Fig. 6.6): it cuts the opacity of materials on one side of
// it and keeps their refraction, so the inside of a scan shows through the part cut away, bent by
// it. The plane goes through `point`; the side `normal` points to stays. On the other side the
// listed materials (all when `materials` is empty) absorb, scatter and emit nothing, while their
// n, its gradient and their Fresnel surfaces stay as they were (shaders/shared/optics.h
// materialClipWeight: a ramp one voxel wide across the plane, so the cut is not a staircase).
struct ClipPlaneSpec {
    glm::vec3 point{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};  // unit length; points into the part that stays
    std::vector<std::string> materials;  // names in Scene::materials; empty: every material
    std::string jsonPath;                // e.g. "/clip_planes/0"
};

// The curve between exposure and the sRGB encoding of PNG output and the viewer
// (shaders/shared/tone_map.h). EXR output stays linear.
enum class ToneCurve { Linear, Filmic };

struct RenderSettings {
    int width = 640;
    int height = 480;
    float stepVoxels = 1.0f;  // view-ray step, in voxels of the render volume
    // How curved view rays step through the ray equation (core/ray_integrator.h). Verlet: as
    // accurate as RK4 at the default step for 12 % more view time than Euler, where RK4 takes 50 %
    // (BENCHMARKS.md, curved view rays).
    RayIntegrator integrator = RayIntegrator::Verlet;
    float minTransmittance = 1e-3f;  // a view ray stops when every channel is below this
    // Fresnel at the sharp surfaces of refracting materials (MaterialSpec::fresnel) for view rays
    // (shaders/shared/fresnel.h): where a curved view ray crosses one, its transmittance is scaled
    // by 1 − R and R × the environment in the mirror direction is added (Ihrke et al. 2007 §5).
    // A crossing is where n_surface changes by more than surfaceSlope per voxel.
    bool fresnel = true;
    float surfaceSlope = 0.01f;
    float exposure = 0.0f;  // stops; the tone map multiplies by 2^exposure
    ToneCurve toneCurve = ToneCurve::Filmic;
    std::uint32_t seed = 0;
    // render.light_transport as written (compact JSON): the method and each method's settings
    // section. Core does not know the methods; they read it themselves
    // (render/light_transport_registry.h), errors at "<file>:/render/light_transport/...".
    std::string lightTransport = "{}";
};

struct OutputSettings {
    std::string directory = "out";
    std::string name = "frame";  // files are <directory>/<name>_<frame 4 digits>.png / .exr
    bool nameSet = false;        // the scene gave "name" (a simulation cache then takes it)
    bool png = true;
    bool exr = false;
};

struct TimeSettings {
    double fps = 24.0;
    int frameStart = 0;
    int frameEnd = 0;  // inclusive
};

// A keyframe track (docs/scene-format.md#animation): one animatable value of the scene, its keys
// and how to interpolate between them. Targets are JSON pointers into the scene as written, e.g.
// "/lights/0/position", "/meshes/1/rotation", "/materials/2/absorption", "/camera/look_at".
enum class Interpolation { Step, Linear, CatmullRom, CubicSpline };

struct AnimationTrack {
    std::string target;  // the JSON pointer, as written
    Interpolation interpolation = Interpolation::Linear;
    std::vector<double> times;  // seconds, strictly increasing
    // `width` numbers per key (1 scalar, 3 vec3, 4 quaternion [x, y, z, w]); CubicSpline keys
    // hold glTF's triple (in-tangent, value, out-tangent), 3·width numbers.
    int width = 1;
    std::vector<float> values;
    std::string jsonPath;  // e.g. "/animation/0"
};

struct Scene {
    std::string path;  // the file it came from; empty when built in code
    VolumeSettings volume;
    std::vector<SourceSpec> sources;
    // The scene's materials, then those the parser made for the meshes (see MeshObjectSpec).
    std::vector<MaterialSpec> materials;
    std::vector<MeshObjectSpec> meshes;
    std::vector<LightSpec> lights;
    std::vector<ReceiverSpec> receivers;
    std::vector<ClipPlaneSpec> clipPlanes;
    CameraSpec camera;
    EnvironmentSpec environment;
    RenderSettings render;
    OutputSettings output;
    TimeSettings time;
    // The smoke domains `eikon simulate` steps (and sources of type Simulation show live): none,
    // one ("simulation": {...}) or several ("simulation": [{...}, ...], each labelled).
    std::vector<SmokeSimulationSpec> simulations;
    std::vector<AnimationTrack> animation;  // sim/animation.h evaluates them
};

// The two fields a mesh writes: its coverage (absorption, scattering, emission read it) and its
// blurred coverage (n reads it): "<name>" and "<name>.n".
struct MeshFieldNames {
    std::string coverage;
    std::string index;
};
MeshFieldNames meshMaterialFieldNames(const MeshObjectSpec& mesh);
// The mesh index whose field `field` is, or −1 for fields sources write.
int meshOfField(const Scene& scene, const std::string& field);

// Reads and validates a scene file. Throws eikon::Error naming the file and JSON path.
Scene loadScene(const std::string& path);
// Same, from text; `fileForMessages` is used in errors and to resolve relative paths.
Scene parseScene(const std::string& jsonText, const std::string& fileForMessages);

// The scene `eikon render cache.vdb` uses: the file as its only source, a grey smoke material on
// its density, automatic bounds and resolution, one directional light from the upper right
// front, black background, and an automatic camera framing the density that shows (at least
// kVisibleFraction of its largest value, core/density_view.h), up along `choices.up` or the axis
// the file implies (the rule: core/default_scene.cpp chooseUp). `note` gets a line saying how the
// up axis was chosen when the data chose it ("" otherwise).
// A file with no density grid, or `choices.grid` given, is a solid: its level set
// (core/level_set.h) as glass over a floor under a sun, whose caustic the photons draw on the
// floor; `note` then says so.
struct DefaultSceneChoices {
    std::optional<glm::vec3> up;  // --up
    GridChoice grid;              // --grid: the level set to render
};
Scene defaultSceneForVdb(const std::string& vdbPath, const DefaultSceneChoices& choices,
                         std::string& note);
// The same look on a sequence (core/vdb_sequence.h: one frame's file or a pattern), its frames
// the scene's frame_start to frame_end, images named as the cache (output.name
// "fluid_data_####"), framed once on its first, middle and last frames. `holdMissingFrames` as
// the scene key "missing_frames": "hold".
Scene defaultSceneForVdbSequence(const std::string& fileOrPattern, bool holdMissingFrames,
                                 const DefaultSceneChoices& choices, std::string& note);

}  // namespace eikon
