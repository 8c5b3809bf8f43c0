// `import eikon`: the C++ API (include/eikon/) for Python, on pybind11. Images come back as numpy
// arrays over the image's own memory (no copy: the array keeps the image alive); fields as dense
// numpy copies of their active box (a sparse tree has no array layout to share). The GIL is
// released while a scene loads, steps or renders, so other Python threads run meanwhile.
// eikon.Error (a RuntimeError) carries the command line's one-line message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include <eikon/eikon.h>
#include <eikon/fields.h>

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

// A numpy view of `data` owned by the Python object `owner` (an Image): no copy.
template <typename T>
py::array_t<T> view(const std::vector<T>& data, std::vector<py::ssize_t> shape, py::object owner) {
    std::vector<py::ssize_t> strides(shape.size());
    py::ssize_t stride = sizeof(T);
    for (size_t i = shape.size(); i-- > 0;) {
        strides[i] = stride;
        stride *= shape[i];
    }
    py::array_t<T> a(shape, strides, data.data(), owner);
    // Read-only: the image is what was rendered; numpy.array(a) gives a copy to change.
    a.attr("setflags")("write"_a = false);
    return a;
}

// A field's active box as a dense array indexed [i - i0, j - j0, k - k0] (as pyopenvdb's
// copyToArray), with the box's first index.
template <typename GridT, typename T, int C>
py::tuple denseOf(const GridT& grid) {
    const openvdb::CoordBBox box = grid.evalActiveVoxelBoundingBox();
    const openvdb::Coord lo = box.min(), dim = box.empty() ? openvdb::Coord(0) : box.dim();
    std::vector<py::ssize_t> shape{dim.x(), dim.y(), dim.z()};
    if (C > 1) shape.push_back(C);
    py::array_t<T> a(shape);
    T* raw = a.mutable_data();
    auto acc = grid.getConstAccessor();
    size_t n = 0;
    for (int i = 0; i < dim.x(); ++i)
        for (int j = 0; j < dim.y(); ++j)
            for (int k = 0; k < dim.z(); ++k) {
                const auto v = acc.getValue(lo.offsetBy(i, j, k));
                if constexpr (C == 1)
                    raw[n++] = T(v);
                else
                    for (int c = 0; c < C; ++c) raw[n++] = T(v[c]);
            }
    return py::make_tuple(a, py::make_tuple(lo.x(), lo.y(), lo.z()));
}

py::tuple fieldArray(eikon::Session& session, const std::string& name) {
    const openvdb::GridBase::ConstPtr grid = eikon::fieldGrid(session, name);
    if (auto g = openvdb::gridConstPtrCast<openvdb::FloatGrid>(grid))
        return denseOf<openvdb::FloatGrid, float, 1>(*g);
    if (auto g = openvdb::gridConstPtrCast<openvdb::DoubleGrid>(grid))
        return denseOf<openvdb::DoubleGrid, double, 1>(*g);
    if (auto g = openvdb::gridConstPtrCast<openvdb::Vec3SGrid>(grid))
        return denseOf<openvdb::Vec3SGrid, float, 3>(*g);
    throw eikon::Error("field '" + name + "'",
                       "of grid type " + grid->type() + ", which has no numpy form here");
}

// The field as a pyopenvdb grid: written to a temporary VDB file by Eikon's exporter and read
// there by pyopenvdb (the two wrap OpenVDB separately; a file is the one form both read).
py::object fieldPyopenvdb(eikon::Session& session, const std::string& name) {
    py::module_ vdb = py::module_::import("pyopenvdb");
    const auto grid = eikon::fieldGrid(session, name);
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() /
        ("eikon_field_" + std::to_string(reinterpret_cast<std::uintptr_t>(grid.get())) + ".vdb");
    eikon::writeFields(file.string(), {grid});
    py::object out = vdb.attr("read")(file.string(), grid->getName());
    std::error_code ec;
    std::filesystem::remove(file, ec);
    return out;
}

py::dict metricsDict(const eikon::ImageMetrics& m) {
    return py::dict("rmse"_a = m.rmse, "max_abs"_a = m.maxAbs, "mean_relative"_a = m.meanRelative,
                    "psnr"_a = m.psnr, "ssim"_a = m.ssim);
}

}  // namespace

PYBIND11_MODULE(eikon, m) {
    m.doc() = "Eikon: relighting of refractive, absorbing and scattering media (docs: README.md)";
    py::register_exception<eikon::Error>(m, "Error", PyExc_RuntimeError);

    py::enum_<eikon::Device>(m, "Device")
        .value("AUTO", eikon::Device::Auto)
        .value("GPU", eikon::Device::Gpu)
        .value("CPU", eikon::Device::Cpu);
    py::enum_<eikon::LightKind>(m, "LightKind")
        .value("POINT", eikon::LightKind::Point)
        .value("DIRECTIONAL", eikon::LightKind::Directional)
        .value("SPOT", eikon::LightKind::Spot);

    py::class_<eikon::RenderedImage>(m, "Image")
        .def_readonly("frame", &eikon::RenderedImage::frame)
        .def_readonly("width", &eikon::RenderedImage::width)
        .def_readonly("height", &eikon::RenderedImage::height)
        .def_readonly("linear", &eikon::RenderedImage::linear)
        .def_property_readonly("rgb",
                               [](py::object self) {
                                   const auto& im = self.cast<const eikon::RenderedImage&>();
                                   return view(im.rgb, {im.height, im.width, 3}, self);
                               })
        .def_property_readonly("srgb8",
                               [](py::object self) {
                                   const auto& im = self.cast<const eikon::RenderedImage&>();
                                   return view(im.srgb8, {im.height, im.width, 3}, self);
                               })
        .def_property_readonly("transmittance",
                               [](py::object self) {
                                   const auto& im = self.cast<const eikon::RenderedImage&>();
                                   return view(im.transmittance, {im.height, im.width}, self);
                               })
        .def("write", &eikon::RenderedImage::write, "path"_a,
             "the PNG (or .exr: linear EXR) eikon render writes for this frame");

    py::class_<eikon::Camera>(m, "Camera")
        .def(py::init<>())
        .def_readwrite("position", &eikon::Camera::position)
        .def_readwrite("look_at", &eikon::Camera::lookAt)
        .def_readwrite("up", &eikon::Camera::up)
        .def_readwrite("horizontal_fov_degrees", &eikon::Camera::horizontalFovDegrees);
    py::class_<eikon::Light>(m, "Light")
        .def(py::init<>())
        .def_readwrite("kind", &eikon::Light::kind)
        .def_readwrite("position", &eikon::Light::position)
        .def_readwrite("direction", &eikon::Light::direction)
        .def_readwrite("color", &eikon::Light::color)
        .def_readwrite("intensity", &eikon::Light::intensity)
        .def_readwrite("cone_angle_degrees", &eikon::Light::coneAngleDegrees)
        .def_readwrite("cone_softness_degrees", &eikon::Light::coneSoftnessDegrees)
        .def_readwrite("angular_diameter_degrees", &eikon::Light::angularDiameterDegrees);
    py::class_<eikon::Material>(m, "Material")
        .def(py::init<>())
        .def_readwrite("name", &eikon::Material::name)
        .def_readonly("field", &eikon::Material::field)
        .def_readwrite("absorption", &eikon::Material::absorption)
        .def_readwrite("scattering", &eikon::Material::scattering)
        .def_readwrite("anisotropy", &eikon::Material::anisotropy)
        .def_readwrite("emission", &eikon::Material::emission)
        .def_readwrite("ior", &eikon::Material::ior)
        .def_readwrite("abbe", &eikon::Material::abbe)
        .def_readwrite("transfer", &eikon::Material::transfer)
        .def_readwrite("particle_color_map", &eikon::Material::particleColorMap)
        .def_readwrite("particle_color_range", &eikon::Material::particleColorRange)
        .def_readwrite("particle_color_points", &eikon::Material::particleColorPoints);

    using eikon::Session;
    py::class_<Session>(m, "Session")
        .def_static(
            "open",
            [](const std::string& path, eikon::Device device) {
                py::gil_scoped_release unlocked;
                return Session::open(path, device);
            },
            "path"_a, "device"_a = eikon::Device::Auto,
            "a scene file, a VDB file or a VDB sequence pattern")
        .def_static(
            "from_json",
            [](const std::string& json, const std::string& base, eikon::Device device) {
                py::gil_scoped_release unlocked;
                return Session::fromJson(json, base, device);
            },
            "json"_a, "base_directory"_a = ".", "device"_a = eikon::Device::Auto)
        .def_property_readonly("first_frame", &Session::firstFrame)
        .def_property_readonly("last_frame", &Session::lastFrame)
        .def_property_readonly("device_description", &Session::deviceDescription)
        .def("step_to", &Session::stepTo, "frame"_a, py::call_guard<py::gil_scoped_release>())
        .def("render", &Session::render, "frame"_a, py::call_guard<py::gil_scoped_release>())
        .def_property("camera", &Session::camera, &Session::setCamera)
        .def("set_image_size", &Session::setImageSize, "width"_a, "height"_a)
        .def_property_readonly("light_count", &Session::lightCount)
        .def("light", &Session::light, "index"_a)
        .def("set_light", &Session::setLight, "index"_a, "light"_a)
        .def_property_readonly("material_names", &Session::materialNames)
        .def("material", &Session::material, "name"_a)
        .def("set_material", &Session::setMaterial, "material"_a)
        .def("field_names", [](Session& s) { return eikon::fieldNames(s); })
        .def("field", &fieldArray, "name"_a,
             "(array, (i0, j0, k0)): the field's active box, indexed [i - i0, j - j0, k - k0]")
        .def("field_pyopenvdb", &fieldPyopenvdb, "name"_a,
             "the field as a pyopenvdb grid (a copy, through a temporary VDB file)");

    m.def(
        "compare_images",
        [](const eikon::RenderedImage& test, const eikon::RenderedImage& reference) {
            return metricsDict(eikon::compareImages(test, reference));
        },
        "test"_a, "reference"_a,
        "rmse, max_abs, mean_relative, psnr, ssim as eikon regress measures them");
    m.def("read_image", &eikon::readImage, "path"_a, "a PNG (display values) or EXR (linear)");
}
