#include "app/contact_sheet.hpp"

#include "core/atomic_file.hpp"

#include <airlight/error.hpp>

#include <cairo.h>
#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>

namespace airlight::app {

glm::dvec3 inferno(double t) {
  static constexpr std::array<std::array<double, 3>, 9> stops{{{0, 0, 4},
                                                                {31, 12, 72},
                                                                {85, 15, 109},
                                                                {136, 34, 106},
                                                                {186, 54, 85},
                                                                {227, 89, 51},
                                                                {249, 140, 10},
                                                                {249, 201, 50},
                                                                {252, 255, 164}}};
  const double x = std::clamp(t, 0.0, 1.0) * (stops.size() - 1);
  const size_t i = std::min(static_cast<size_t>(x), stops.size() - 2);
  const double f = x - static_cast<double>(i);
  glm::dvec3 c;
  for (int k = 0; k < 3; ++k) c[k] = ((1.0 - f) * stops[i][k] + f * stops[i + 1][k]) / 255.0;
  return c;
}

namespace {

constexpr int margin = 8, line_h = 14, label_lines = 4, min_cell_w = 190, bar_h = 12;
constexpr double font_size = 11.0;

using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using ContextPtr = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

std::uint32_t rgb24(double r, double g, double b) {
  auto byte = [](double v) { return static_cast<std::uint32_t>(std::lround(255.0 * std::clamp(v, 0.0, 1.0))); };
  return byte(r) << 16 | byte(g) << 8 | byte(b);
}

// A w·scale × h·scale surface, each pixel repeated scale² times (nearest
// neighbour, so that single-pixel artefacts stay sharp).
SurfacePtr pixel_surface(int w, int h, int scale, const std::function<std::uint32_t(int, int)>& color) {
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w * scale, h * scale), cairo_surface_destroy);
  unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  for (int y = 0; y < h * scale; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<ptrdiff_t>(y) * stride);
    for (int x = 0; x < w * scale; ++x) row[x] = color(x / scale, y / scale);
  }
  cairo_surface_mark_dirty(surface.get());
  return surface;
}

SurfacePtr tone_mapped(const Image& image, int scale, const ToneMap& tone) {
  return pixel_surface(image.width, image.height, scale, [&](int x, int y) {
    const glm::vec3 p = tone_map(image.at(x, y), tone);
    return rgb24(p.r, p.g, p.b);
  });
}

float abs_error(const Image& image, const Image& reference, int x, int y) {
  const glm::vec3 d = glm::abs(image.at(x, y) - reference.at(x, y));
  return std::max({d.r, d.g, d.b});
}

SurfacePtr heat_map(const Image& image, const Image& reference, int scale, double max_error) {
  return pixel_surface(image.width, image.height, scale, [&](int x, int y) {
    const glm::dvec3 c = inferno(abs_error(image, reference, x, y) / max_error);
    return rgb24(c.r, c.g, c.b);
  });
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// Lines no wider than `width`, broken between words; the last line shown ends
// in "…" when the text does not fit in `max_lines`.
std::vector<std::string> wrap(cairo_t* cr, const std::string& text, double width, size_t max_lines) {
  std::vector<std::string> lines{""};
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = std::min(text.find(' ', start), text.size());
    const std::string word = text.substr(start, end - start);
    const std::string joined = lines.back().empty() ? word : lines.back() + " " + word;
    cairo_text_extents_t extents;
    cairo_text_extents(cr, joined.c_str(), &extents);
    if (extents.x_advance > width && !lines.back().empty()) {
      if (lines.size() == max_lines) {
        lines.back() += " …";
        break;
      }
      lines.push_back(word);
    } else {
      lines.back() = joined;
    }
    start = end + 1;
  }
  return lines;
}

void text_at(cairo_t* cr, double x, double y, const std::string& text) {
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

void draw_label(cairo_t* cr, const SheetEntry& e, double x, double y, double width) {
  cairo_set_source_rgb(cr, 0, 0, 0);
  std::vector<std::string> lines{e.method + (e.note.empty() ? "" : " (" + e.note + ")")};
  for (const auto& line : wrap(cr, e.settings, width, label_lines - 2))
    lines.push_back(line);
  lines.resize(label_lines - 1);
  lines.push_back(format("%.3g s", e.seconds) + "   rRMSE " + format("%.3g", e.rel_rmse));
  for (size_t i = 0; i < lines.size(); ++i) text_at(cr, x, y + line_h * (i + 1.0) - 3.0, lines[i]);
}

void paint(cairo_t* cr, cairo_surface_t* surface, double x, double y) {
  cairo_set_source_surface(cr, surface, x, y);
  cairo_paint(cr);
}

void set_font(cairo_t* cr) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, font_size);
}

// The colour bar's caption, wrapped to `width`: a sheet of two columns is ~400 px
// wide, too narrow for the scale's sentence on one line.
std::vector<std::string> bar_caption(const HeatScale& scale, double width) {
  SurfacePtr scratch(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1), cairo_surface_destroy);
  ContextPtr context(cairo_create(scratch.get()), cairo_destroy);
  set_font(context.get());
  std::vector<std::string> lines =
      wrap(context.get(), "error maps: |image - reference|, largest over RGB, W/(m^2 sr), one scale for all", width, 2);
  for (const auto& line : wrap(context.get(), describe(scale), width, 3)) lines.push_back(line);
  return lines;
}

// The heat maps' colour scale under its caption, ticks at quarters of its top,
// the last one "≥ top".
void draw_color_bar(cairo_t* cr, double x, double y, double width, const std::vector<std::string>& caption,
                     double max_error) {
  cairo_set_source_rgb(cr, 0, 0, 0);
  for (size_t i = 0; i < caption.size(); ++i) text_at(cr, x, y + line_h * (i + 1.0) - 3.0, caption[i]);
  const double bar_y = y + line_h * static_cast<double>(caption.size());
  const SurfacePtr bar = pixel_surface(static_cast<int>(width), bar_h, 1, [&](int i, int) {
    const glm::dvec3 c = inferno(i / (width - 1.0));
    return rgb24(c.r, c.g, c.b);
  });
  paint(cr, bar.get(), x, bar_y);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.0);
  for (int k = 0; k <= 4; ++k) {
    const std::string tick = (k == 4 ? "≥ " : "") + format("%.3g", max_error * k / 4.0);
    cairo_text_extents_t extents;
    cairo_text_extents(cr, tick.c_str(), &extents);
    const double tx = x + (width - 1.0) * k / 4.0;
    cairo_move_to(cr, std::round(tx) + 0.5, bar_y + bar_h);
    cairo_line_to(cr, std::round(tx) + 0.5, bar_y + bar_h + 4.0);
    cairo_stroke(cr);
    const double left = std::clamp(tx - extents.x_advance / 2.0, x, x + width - extents.x_advance);
    text_at(cr, left, bar_y + bar_h + 4.0 + line_h - 3.0, tick);
  }
}

}  // namespace

HeatScale heat_scale(const std::vector<SheetEntry>& entries) {
  const Image& reference = *entries.at(0).image;
  std::vector<double> errors;
  for (size_t i = 1; i < entries.size(); ++i)
    for (int y = 0; y < reference.height; ++y)
      for (int x = 0; x < reference.width; ++x)
        if (const double e = abs_error(*entries[i].image, reference, x, y); e > 0.0) errors.push_back(e);
  if (errors.empty()) return {};
  const size_t rank = static_cast<size_t>(std::ceil(0.99 * static_cast<double>(errors.size())));  // 1-based
  std::nth_element(errors.begin(), errors.begin() + (rank - 1), errors.end());
  const double top = errors[rank - 1];
  return {top, *std::max_element(errors.begin() + (rank - 1), errors.end())};  // the tail holds the largest
}

std::string describe(const HeatScale& scale) {
  return "scale 0 to " + format("%.3g", scale.top) +
         " W/(m^2 sr): the 99th percentile of the nonzero errors; larger ones, up to " +
         format("%.3g", scale.largest) + ", saturate";
}

void write_contact_sheet(const std::vector<SheetEntry>& entries, const HeatScale& scale, const ToneMap& tone,
                         const std::filesystem::path& file) {
  const Image& reference = *entries.at(0).image;
  const int zoom = reference.width < 256 ? 2 : 1;  // 128×96 images would be too small to read
  const int image_w = reference.width * zoom, image_h = reference.height * zoom;
  const int cell_w = std::max(image_w, min_cell_w), label_h = label_lines * line_h + 4;
  const int n = static_cast<int>(entries.size());
  const int sheet_w = margin + n * (cell_w + margin);
  const int heat_y = margin + label_h + image_h + margin, bar_y = heat_y + image_h + margin;
  const std::vector<std::string> caption = bar_caption(scale, sheet_w - 2 * margin);
  const int sheet_h = bar_y + static_cast<int>(caption.size()) * line_h + bar_h + 4 + line_h + margin;

  SurfacePtr sheet(cairo_image_surface_create(CAIRO_FORMAT_RGB24, sheet_w, sheet_h), cairo_surface_destroy);
  ContextPtr context(cairo_create(sheet.get()), cairo_destroy);
  cairo_t* cr = context.get();
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  set_font(cr);
  for (int i = 0; i < n; ++i) {
    const SheetEntry& e = entries[i];
    const double x = margin + i * (cell_w + margin), image_x = x + (cell_w - image_w) / 2;
    draw_label(cr, e, x, margin, cell_w);
    paint(cr, tone_mapped(*e.image, zoom, tone).get(), image_x, margin + label_h);
    paint(cr, heat_map(*e.image, reference, zoom, scale.top).get(), image_x, heat_y);
  }
  draw_color_bar(cr, margin, bar_y, sheet_w - 2 * margin, caption, scale.top);
  cairo_surface_flush(sheet.get());
  write_atomically(file, [&](const std::filesystem::path& temp) {
    if (const cairo_status_t status = cairo_surface_write_to_png(sheet.get(), temp.c_str());
        status != CAIRO_STATUS_SUCCESS)
      throw Failure("cannot write " + temp.string() + ": " + cairo_status_to_string(status));
  });
}

}  // namespace airlight::app
