// stb_image compiled into the fuzz executables, from the same Debian header that
// libstb.so is built from: the executable's definitions take precedence over the shared
// library's, so libFuzzer sees coverage inside the decoders and ASan checks them.
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
