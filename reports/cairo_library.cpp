// cairo, loaded when the first plot, PDF page or picture is drawn instead of at program start:
// libcairo pulls in X11, xcb, fontconfig, freetype and pixman, a fifth of the start-up time of a
// command that draws nothing (`feedflow design` without --report, `version`). The program does
// not link libcairo; the cairo functions reports/ calls are defined here as forwarders (see
// models/os/shared_library.hpp). A call to a cairo function not listed here fails to link:
// add it below (the compiler checks the signature against cairo.h).
#include <cairo-pdf.h>
#include <cairo.h>

#include "models/os/shared_library.hpp"

namespace {

const feedflow::SharedLibrary& cairo_library() {
  static const feedflow::SharedLibrary library({"libcairo.so.2", "libcairo.so"}, "libcairo2",
                                               "drawing plots, pictures and the PDF report");
  return library;
}

}  // namespace

FEEDFLOW_FORWARD(cairo_library(), void, cairo_arc,
                 (cairo_t* cr, double xc, double yc, double radius, double angle1, double angle2),
                 (cr, xc, yc, radius, angle1, angle2))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_clip, (cairo_t* cr), (cr))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_close_path, (cairo_t* cr), (cr))
FEEDFLOW_FORWARD(cairo_library(), cairo_t*, cairo_create, (cairo_surface_t* target), (target))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_destroy, (cairo_t* cr), (cr))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_fill, (cairo_t* cr), (cr))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_fill_preserve, (cairo_t* cr), (cr))
FEEDFLOW_FORWARD(cairo_library(), cairo_surface_t*, cairo_image_surface_create,
                 (cairo_format_t format, int width, int height), (format, width, height))
FEEDFLOW_FORWARD(cairo_library(), cairo_surface_t*, cairo_image_surface_create_from_png,
                 (const char* filename), (filename))
FEEDFLOW_FORWARD(cairo_library(), cairo_surface_t*, cairo_image_surface_create_from_png_stream,
                 (cairo_read_func_t read_func, void* closure), (read_func, closure))
FEEDFLOW_FORWARD(cairo_library(), unsigned char*, cairo_image_surface_get_data,
                 (cairo_surface_t* surface), (surface))
FEEDFLOW_FORWARD(cairo_library(), cairo_format_t, cairo_image_surface_get_format,
                 (cairo_surface_t* surface), (surface))
FEEDFLOW_FORWARD(cairo_library(), int, cairo_image_surface_get_height, (cairo_surface_t* surface),
                 (surface))
FEEDFLOW_FORWARD(cairo_library(), int, cairo_image_surface_get_stride, (cairo_surface_t* surface),
                 (surface))
FEEDFLOW_FORWARD(cairo_library(), int, cairo_image_surface_get_width, (cairo_surface_t* surface),
                 (surface))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_line_to, (cairo_t* cr, double x, double y),
                 (cr, x, y))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_move_to, (cairo_t* cr, double x, double y),
                 (cr, x, y))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_new_path, (cairo_t* cr), (cr))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_paint, (cairo_t* cr), (cr))
FEEDFLOW_FORWARD(cairo_library(), cairo_surface_t*, cairo_pdf_surface_create,
                 (const char* filename, double width_in_points, double height_in_points),
                 (filename, width_in_points, height_in_points))
FEEDFLOW_FORWARD(cairo_library(), cairo_surface_t*, cairo_pdf_surface_create_for_stream,
                 (cairo_write_func_t write_func, void* closure, double width_in_points,
                  double height_in_points),
                 (write_func, closure, width_in_points, height_in_points))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_pdf_surface_set_metadata,
                 (cairo_surface_t* surface, cairo_pdf_metadata_t metadata, const char* utf8),
                 (surface, metadata, utf8))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_rectangle,
                 (cairo_t* cr, double x, double y, double width, double height),
                 (cr, x, y, width, height))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_restore, (cairo_t* cr), (cr))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_rotate, (cairo_t* cr, double angle), (cr, angle))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_save, (cairo_t* cr), (cr))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_scale, (cairo_t* cr, double sx, double sy),
                 (cr, sx, sy))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_select_font_face,
                 (cairo_t* cr, const char* family, cairo_font_slant_t slant,
                  cairo_font_weight_t weight),
                 (cr, family, slant, weight))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_set_dash,
                 (cairo_t* cr, const double* dashes, int num_dashes, double offset),
                 (cr, dashes, num_dashes, offset))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_set_font_size, (cairo_t* cr, double size),
                 (cr, size))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_set_line_width, (cairo_t* cr, double width),
                 (cr, width))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_set_source_rgb,
                 (cairo_t* cr, double red, double green, double blue), (cr, red, green, blue))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_set_source_rgba,
                 (cairo_t* cr, double red, double green, double blue, double alpha),
                 (cr, red, green, blue, alpha))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_set_source_surface,
                 (cairo_t* cr, cairo_surface_t* surface, double x, double y), (cr, surface, x, y))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_show_page, (cairo_t* cr), (cr))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_show_text, (cairo_t* cr, const char* utf8),
                 (cr, utf8))
FEEDFLOW_FORWARD(cairo_library(), cairo_status_t, cairo_status, (cairo_t* cr), (cr))
FEEDFLOW_FORWARD(cairo_library(), const char*, cairo_status_to_string, (cairo_status_t status),
                 (status))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_stroke, (cairo_t* cr), (cr))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_surface_destroy, (cairo_surface_t* surface),
                 (surface))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_surface_finish, (cairo_surface_t* surface),
                 (surface))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_surface_flush, (cairo_surface_t* surface), (surface))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_surface_mark_dirty, (cairo_surface_t* surface),
                 (surface))
FEEDFLOW_FORWARD(cairo_library(), cairo_status_t, cairo_surface_status, (cairo_surface_t* surface),
                 (surface))
FEEDFLOW_FORWARD(cairo_library(), cairo_status_t, cairo_surface_write_to_png,
                 (cairo_surface_t* surface, const char* filename), (surface, filename))
FEEDFLOW_FORWARD(cairo_library(), cairo_status_t, cairo_surface_write_to_png_stream,
                 (cairo_surface_t* surface, cairo_write_func_t write_func, void* closure),
                 (surface, write_func, closure))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_text_extents,
                 (cairo_t* cr, const char* utf8, cairo_text_extents_t* extents),
                 (cr, utf8, extents))
FEEDFLOW_FORWARD(cairo_library(), void, cairo_translate, (cairo_t* cr, double tx, double ty),
                 (cr, tx, ty))
