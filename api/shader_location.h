#pragma once
namespace eikon {
// Points the renderer at the installed shaders (api/shader_location.cpp); called by every Session.
void useInstalledShaders();
}  // namespace eikon
