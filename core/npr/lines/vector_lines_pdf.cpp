// Lines as PDF, through cairo's PDF surface. cairo writes to a stream we keep in
// memory, so the file is replaced atomically like every other output.
#include "core/image/image_io.h"
#include "core/io/atomic_file.h"
#include "core/npr/lines/stroke_outline.h"
#include "core/npr/lines/vector_lines.h"

#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>

namespace inkray {
namespace {

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

double srgb_of(float display) { return double(linear_to_srgb(std::clamp(display, 0.f, 1.f))); }

// The background as an opaque 8-bit sRGB image surface, scaled over the page.
void paint_background(cairo_t* cr, const RgbImage& image, int width, int height) {
  const std::vector<uint8_t> rgb = encode_srgb8(image);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, image.width, image.height);
  cairo_surface_flush(surface);
  unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  if (data) {
    for (int y = 0; y < image.height; ++y) {
      auto* row = reinterpret_cast<uint32_t*>(data + size_t(y) * size_t(stride));
      for (int x = 0; x < image.width; ++x) {
        const uint8_t* p = &rgb[(size_t(y) * size_t(image.width) + size_t(x)) * 3];
        row[x] = 0xff000000u | uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | uint32_t(p[2]);
      }
    }
  }
  cairo_surface_mark_dirty(surface);
  cairo_save(cr);
  cairo_scale(cr, double(width) / image.width, double(height) / image.height);
  cairo_set_source_surface(cr, surface, 0, 0);
  cairo_paint(cr);
  cairo_restore(cr);
  cairo_surface_destroy(surface);
}

void fill_shape(cairo_t* cr, const OutlineShape& shape) {
  for (const std::vector<Vec2>& ring : shape.rings) {
    for (size_t k = 0; k < ring.size(); ++k) {
      if (k == 0)
        cairo_move_to(cr, ring[k].x, ring[k].y);
      else
        cairo_line_to(cr, ring[k].x, ring[k].y);
    }
    cairo_close_path(cr);
  }
  cairo_set_source_rgba(cr, srgb_of(shape.color.r), srgb_of(shape.color.g), srgb_of(shape.color.b),
                        std::clamp(shape.opacity, 0.f, 1.f));
  cairo_fill(cr);
}

}  // namespace

bool encode_lines_pdf(int width, int height, const std::vector<LineStroke>& strokes,
                      const RgbImage* background, std::string* bytes, std::string* error) {
  if (width <= 0 || height <= 0) {
    *error = "cannot write lines of an empty image";
    return false;
  }
  std::string pdf;
  cairo_surface_t* surface = cairo_pdf_surface_create_for_stream(append_bytes, &pdf, width, height);
  cairo_t* cr = cairo_create(surface);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
  if (background && background->width > 0 && background->height > 0)
    paint_background(cr, *background, width, height);
  for (const LineStroke& stroke : strokes)
    for (const OutlineShape& shape : stroke_outline(stroke)) fill_shape(cr, shape);
  cairo_show_page(cr);
  const cairo_status_t drawn = cairo_status(cr);
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const cairo_status_t finished = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  const cairo_status_t status = drawn != CAIRO_STATUS_SUCCESS ? drawn : finished;
  if (status != CAIRO_STATUS_SUCCESS) {
    *error = std::string("PDF drawing failed: ") + cairo_status_to_string(status);
    return false;
  }
  *bytes = std::move(pdf);
  return true;
}

bool write_lines_pdf(const std::filesystem::path& file, int width, int height,
                     const std::vector<LineStroke>& strokes, const RgbImage* background, std::string* error) {
  std::string pdf;
  if (!encode_lines_pdf(width, height, strokes, background, &pdf, error)) {
    *error = file.string() + ": " + *error;
    return false;
  }
  return write_file_atomically(file, pdf, error);
}

}  // namespace inkray
