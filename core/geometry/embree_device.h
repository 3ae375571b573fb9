// The process-wide Embree device, shared by the render BVH and by the helper
// BVHs other modules build (stroke surfaces), without including Embree here.
#pragma once

struct RTCDeviceTy;

namespace inkray {

// Created on first use; creating a device costs milliseconds and starts the
// worker threads Embree builds BVHs with, so there is only one.
RTCDeviceTy* shared_embree_device();

}  // namespace inkray
