#include "app/plot.hpp"

#include "core/atomic_file.hpp"

#include <airlight/error.hpp>

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace airlight::app {

namespace {

constexpr int width = 1000, height = 620;  // the legend takes the right 300 pixels
constexpr double left = 90, right = 680, top = 50, bottom = 550;  // the plot area, in pixels

// Tableau 10: distinct at a glance and in greyscale print.
constexpr std::array<std::array<double, 3>, 10> palette{{{0.12, 0.47, 0.71},
                                                         {1.00, 0.50, 0.05},
                                                         {0.17, 0.63, 0.17},
                                                         {0.84, 0.15, 0.16},
                                                         {0.58, 0.40, 0.74},
                                                         {0.55, 0.34, 0.29},
                                                         {0.89, 0.47, 0.76},
                                                         {0.50, 0.50, 0.50},
                                                         {0.74, 0.74, 0.13},
                                                         {0.09, 0.75, 0.81}}};

bool plottable(const PlotPoint& p) {
  return std::isfinite(p.seconds) && std::isfinite(p.error) && p.seconds > 0.0 && p.error > 0.0;
}

// Whole decades [lo, hi] of log10 covering the values, at least one decade wide.
struct Decades {
  int lo = -3, hi = 0;
  double fraction(double value) const { return (std::log10(value) - lo) / (hi - lo); }
};

Decades decades(const std::vector<double>& values) {
  if (values.empty()) return {};
  const auto [min, max] = std::minmax_element(values.begin(), values.end());
  Decades d{static_cast<int>(std::floor(std::log10(*min))), static_cast<int>(std::ceil(std::log10(*max)))};
  if (d.hi == d.lo) ++d.hi;
  return d;
}

struct Axes {
  Decades x, y;
  double px(double seconds) const { return left + x.fraction(seconds) * (right - left); }
  double py(double error) const { return bottom - y.fraction(error) * (bottom - top); }
};

void set_color(cairo_t* cr, const std::array<double, 3>& c) { cairo_set_source_rgb(cr, c[0], c[1], c[2]); }

// "10" with the exponent raised, its right edge or centre at (x, y) as `align` is 1 or 0.5.
void decade_label(cairo_t* cr, int exponent, double x, double y, double align) {
  const std::string base = "10", power = std::to_string(exponent);
  cairo_set_font_size(cr, 13);
  cairo_text_extents_t b, p;
  cairo_text_extents(cr, base.c_str(), &b);
  cairo_set_font_size(cr, 9);
  cairo_text_extents(cr, power.c_str(), &p);
  const double x0 = x - align * (b.x_advance + p.x_advance);
  cairo_set_font_size(cr, 13);
  cairo_move_to(cr, x0, y);
  cairo_show_text(cr, base.c_str());
  cairo_set_font_size(cr, 9);
  cairo_move_to(cr, x0 + b.x_advance, y - 6);
  cairo_show_text(cr, power.c_str());
}

void centred_text(cairo_t* cr, const std::string& text, double x, double y, double size) {
  cairo_set_font_size(cr, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  cairo_move_to(cr, x - e.x_advance / 2, y);
  cairo_show_text(cr, text.c_str());
}

void line(cairo_t* cr, double x0, double y0, double x1, double y1) {
  cairo_move_to(cr, x0, y0);
  cairo_line_to(cr, x1, y1);
  cairo_stroke(cr);
}

// Grid and ticks at every decade, minor ticks at 2..9 × each decade, labels, frame.
void draw_axes(cairo_t* cr, const Axes& a) {
  cairo_set_line_width(cr, 1);
  for (int k = a.x.lo; k <= a.x.hi; ++k) {
    const double x = a.px(std::pow(10.0, k));
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    line(cr, x, top, x, bottom);
    cairo_set_source_rgb(cr, 0, 0, 0);
    line(cr, x, bottom, x, bottom + 7);
    decade_label(cr, k, x, bottom + 24, 0.5);
    for (int m = 2; k < a.x.hi && m <= 9; ++m) {
      const double minor = a.px(m * std::pow(10.0, k));
      line(cr, minor, bottom, minor, bottom + 4);
    }
  }
  for (int k = a.y.lo; k <= a.y.hi; ++k) {
    const double y = a.py(std::pow(10.0, k));
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    line(cr, left, y, right, y);
    cairo_set_source_rgb(cr, 0, 0, 0);
    line(cr, left - 7, y, left, y);
    decade_label(cr, k, left - 10, y + 5, 1.0);
    for (int m = 2; k < a.y.hi && m <= 9; ++m) {
      const double minor = a.py(m * std::pow(10.0, k));
      line(cr, left - 4, minor, left, minor);
    }
  }
  cairo_rectangle(cr, left, top, right - left, bottom - top);
  cairo_stroke(cr);
  centred_text(cr, "frame time, median (s)", (left + right) / 2, bottom + 50, 14);
  cairo_save(cr);
  cairo_translate(cr, 28, (top + bottom) / 2);
  cairo_rotate(cr, -M_PI / 2);
  centred_text(cr, "rRMSE of L_air against the reference", 0, 0, 14);
  cairo_restore(cr);
}

void marker(cairo_t* cr, double x, double y, double radius, bool filled) {
  cairo_new_sub_path(cr);
  cairo_arc(cr, x, y, radius, 0, 2 * M_PI);
  filled ? cairo_fill(cr) : cairo_stroke(cr);
}

void draw_series(cairo_t* cr, const Axes& a, const std::vector<PlotPoint>& points,
                 const std::array<double, 3>& color) {
  set_color(cr, color);
  cairo_set_line_width(cr, 2);
  for (size_t i = 0; i < points.size(); ++i) {
    const double x = a.px(points[i].seconds), y = a.py(points[i].error);
    i == 0 ? cairo_move_to(cr, x, y) : cairo_line_to(cr, x, y);
  }
  cairo_stroke(cr);
  for (const auto& p : points) marker(cr, a.px(p.seconds), a.py(p.error), 4, true);
}

// A dashed staircase: from each front point right to the next one's time, then down.
void draw_front(cairo_t* cr, const Axes& a, const std::vector<PlotPoint>& front) {
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.5);
  const double dash[] = {6, 4};
  cairo_set_dash(cr, dash, 2, 0);
  for (size_t i = 0; i < front.size(); ++i) {
    const double x = a.px(front[i].seconds), y = a.py(front[i].error);
    if (i == 0) {
      cairo_move_to(cr, x, y);
    } else {
      cairo_line_to(cr, x, a.py(front[i - 1].error));
      cairo_line_to(cr, x, y);
    }
  }
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
  for (const auto& p : front) marker(cr, a.px(p.seconds), a.py(p.error), 8, false);
}

void draw_legend(cairo_t* cr, const std::vector<PlotSeries>& series) {
  double y = top + 10;
  cairo_set_font_size(cr, 13);
  for (size_t i = 0; i < series.size(); ++i, y += 22) {
    set_color(cr, palette[i % palette.size()]);
    cairo_set_line_width(cr, 2);
    line(cr, right + 20, y, right + 50, y);
    marker(cr, right + 35, y, 4, true);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, right + 58, y + 5);
    cairo_show_text(cr, series[i].label.c_str());
  }
  cairo_set_line_width(cr, 1.5);
  const double dash[] = {6, 4};
  cairo_set_dash(cr, dash, 2, 0);
  line(cr, right + 20, y, right + 50, y);
  cairo_set_dash(cr, nullptr, 0, 0);
  marker(cr, right + 35, y, 8, false);
  cairo_move_to(cr, right + 58, y + 5);
  cairo_show_text(cr, "Pareto front");
}

}  // namespace

std::vector<PlotPoint> pareto_front(const std::vector<PlotPoint>& points) {
  std::vector<PlotPoint> sorted = points;
  std::sort(sorted.begin(), sorted.end(), [](const PlotPoint& a, const PlotPoint& b) {
    return a.seconds != b.seconds ? a.seconds < b.seconds : a.error < b.error;
  });
  std::vector<PlotPoint> front;
  for (const auto& p : sorted)
    if (front.empty() || p.error < front.back().error) front.push_back(p);
  return front;
}

void write_plot(const std::string& title, const std::vector<PlotSeries>& series, const std::filesystem::path& file) {
  std::vector<PlotSeries> shown;
  std::vector<PlotPoint> all;
  std::vector<double> times, errors;
  for (const auto& s : series) {
    PlotSeries kept{s.label, {}};
    std::copy_if(s.points.begin(), s.points.end(), std::back_inserter(kept.points), plottable);
    for (const auto& p : kept.points) {
      all.push_back(p);
      times.push_back(p.seconds);
      errors.push_back(p.error);
    }
    shown.push_back(std::move(kept));
  }
  const Axes axes{decades(times), decades(errors)};

  const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height), cairo_surface_destroy);
  const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> context(cairo_create(surface.get()), cairo_destroy);
  cairo_t* cr = context.get();
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  draw_axes(cr, axes);
  cairo_save(cr);
  cairo_rectangle(cr, left, top, right - left, bottom - top);
  cairo_clip(cr);
  for (size_t i = 0; i < shown.size(); ++i) draw_series(cr, axes, shown[i].points, palette[i % palette.size()]);
  draw_front(cr, axes, pareto_front(all));
  cairo_restore(cr);
  draw_legend(cr, shown);
  cairo_set_source_rgb(cr, 0, 0, 0);
  centred_text(cr, title, width / 2.0, 30, 16);
  write_atomically(file, [&](const std::filesystem::path& temp) {
    if (cairo_surface_write_to_png(surface.get(), temp.c_str()) != CAIRO_STATUS_SUCCESS)
      throw Failure("cannot write " + temp.string());
  });
}

}  // namespace airlight::app
