// EXR files encoded to memory: the one place inkray fills tinyexr's header for writing.
#include "core/image/exr_memory.h"

#include <tinyexr.h>

#include <cstdlib>
#include <cstring>

namespace inkray {

static_assert(kExrUint == TINYEXR_PIXELTYPE_UINT && kExrFloat == TINYEXR_PIXELTYPE_FLOAT);

bool encode_exr_planes(int width, int height, const std::vector<ExrPlane>& planes,
                       const std::map<std::string, ExrAttribute>& attributes, ExrCompression compression,
                       std::string* bytes, std::string* reason) {
  std::vector<unsigned char*> data(planes.size());
  std::vector<EXRChannelInfo> infos(planes.size());
  std::vector<int> types(planes.size()), requested(planes.size());
  for (size_t c = 0; c < planes.size(); ++c) {
    // tinyexr reads the planes and never writes them.
    data[c] = static_cast<unsigned char*>(const_cast<void*>(planes[c].pixels));
    std::memset(&infos[c], 0, sizeof infos[c]);
    std::strncpy(infos[c].name, planes[c].name, sizeof infos[c].name - 1);
    infos[c].pixel_type = types[c] = requested[c] = planes[c].pixel_type;
  }
  EXRImage image;
  InitEXRImage(&image);
  image.images = data.data();
  image.width = width;
  image.height = height;
  image.num_channels = int(planes.size());

  std::vector<EXRAttribute> custom;
  for (const auto& [name, a] : attributes) {
    EXRAttribute e;
    std::memset(&e, 0, sizeof e);
    std::strncpy(e.name, name.c_str(), sizeof e.name - 1);
    std::strncpy(e.type, a.type.c_str(), sizeof e.type - 1);
    e.value = reinterpret_cast<unsigned char*>(const_cast<char*>(a.value.data()));
    e.size = int(a.value.size());
    custom.push_back(e);
  }
  EXRHeader header;
  InitEXRHeader(&header);
  header.compression_type = compression == ExrCompression::zip   ? TINYEXR_COMPRESSIONTYPE_ZIP
                            : compression == ExrCompression::rle ? TINYEXR_COMPRESSIONTYPE_RLE
                                                                 : TINYEXR_COMPRESSIONTYPE_NONE;
  header.num_channels = int(planes.size());
  header.channels = infos.data();
  header.pixel_types = types.data();
  header.requested_pixel_types = requested.data();
  header.num_custom_attributes = int(custom.size());
  header.custom_attributes = custom.data();

  unsigned char* memory = nullptr;
  const char* err = nullptr;
  const size_t size = SaveEXRImageToMemory(&image, &header, &memory, &err);
  if (size == 0 || !memory) {
    *reason = err ? err : "";
    if (err) FreeEXRErrorMessage(err);
    std::free(memory);
    return false;
  }
  bytes->assign(reinterpret_cast<const char*>(memory), size);
  std::free(memory);
  return true;
}

}  // namespace inkray
