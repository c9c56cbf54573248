#pragma once
// Line plots to PNG through gnuplot (Debian: gnuplot-nox), fed on a pipe.
// Host-only.
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

struct PlotSeries {
  std::string title;
  std::vector<double> x, y;
  std::string style = "lines lw 2";
  std::vector<double> y2;  // when given: a band from y to y2 (style "filledcurves ...")
};

struct PlotSpec {
  std::string title, xlabel, ylabel;
  int width = 900, height = 600;
  std::string extra;  // further gnuplot commands, e.g. "set logscale x"
};

inline std::string gnuplot_quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

inline void write_plot_png(const std::string& path, const PlotSpec& spec, const std::vector<PlotSeries>& series) {
  std::FILE* gp = ::popen("gnuplot 2>&1", "w");
  if (!gp) throw std::runtime_error("cannot start gnuplot (install gnuplot-nox)");
  std::fprintf(gp, "set terminal pngcairo size %d,%d enhanced font 'Sans,11'\n", spec.width, spec.height);
  std::fprintf(gp, "set output %s\n", gnuplot_quote(path).c_str());
  std::fprintf(gp, "set title %s\nset xlabel %s\nset ylabel %s\n", gnuplot_quote(spec.title).c_str(),
               gnuplot_quote(spec.xlabel).c_str(), gnuplot_quote(spec.ylabel).c_str());
  std::fprintf(gp, "set grid\nset key top left\n%s\n", spec.extra.c_str());
  std::fprintf(gp, "plot ");
  for (std::size_t s = 0; s < series.size(); ++s)
    std::fprintf(gp, "%s'-' using %s with %s %s", s ? ", " : "", series[s].y2.empty() ? "1:2" : "1:2:3",
                 series[s].style.c_str(),
                 series[s].title.empty() ? "notitle" : ("title " + gnuplot_quote(series[s].title)).c_str());
  std::fprintf(gp, "\n");
  for (const PlotSeries& s : series) {
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (s.y2.empty())
        std::fprintf(gp, "%.10g %.10g\n", s.x[i], s.y[i]);
      else
        std::fprintf(gp, "%.10g %.10g %.10g\n", s.x[i], s.y[i], i < s.y2.size() ? s.y2[i] : s.y[i]);
    }
    std::fprintf(gp, "e\n");
  }
  const int status = ::pclose(gp);
  if (status != 0) throw std::runtime_error("gnuplot failed writing " + path + " (is gnuplot-nox installed?)");
}

}  // namespace vrut
