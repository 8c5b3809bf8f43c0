#pragma once
// The GpuViewParams SSBO at binding EK_SSBO_VIEW_PARAMS (shaders/shared/bindings.h), shared by the
// light-volume passes and the viewing pass of a frame: uploaded once per frame.
#include "shaders/shared/gpu_types.h"

namespace eikon {

class ParamsBuffer {
public:
    ParamsBuffer();
    ~ParamsBuffer();
    ParamsBuffer(const ParamsBuffer&) = delete;
    ParamsBuffer& operator=(const ParamsBuffer&) = delete;
    // Uploads and binds to EK_SSBO_VIEW_PARAMS.
    void upload(const shared::GpuViewParams& params);
    // Binds to EK_SSBO_VIEW_PARAMS what was uploaded last.
    void bind() const;

private:
    unsigned buffer_ = 0;
};

}  // namespace eikon
