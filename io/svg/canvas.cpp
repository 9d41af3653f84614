#include "io/svg/canvas.hpp"

#include <algorithm>

namespace anisocert::io {

Canvas::Canvas(const geometry::Polygon<double>& frame, double margin) : x0_(1e300), x1_(-1e300), y0_(1e300), y1_(-1e300) {
  for (const auto& p : frame) x0_ = std::min(x0_, p.x), x1_ = std::max(x1_, p.x), y0_ = std::min(y0_, p.y), y1_ = std::max(y1_, p.y);
  size_ = std::max(x1_ - x0_, y1_ - y0_);
  margin_ = size_ * margin;
  px_ = 800 / (size_ + 2 * margin_);
  width_ = (x1_ - x0_ + 2 * margin_) * px_;
  height_ = (y1_ - y0_ + 2 * margin_) * px_;
}

std::string xml_text(const std::string& s) {
  std::string e;
  for (char ch : s) e += ch == '&' ? "&amp;" : ch == '<' ? "&lt;" : ch == '>' ? "&gt;" : std::string(1, ch);
  return e;
}

void Canvas::open(std::ostream& o, double footer, double min_width) const {
  const double w = std::max(width_, min_width);
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << height_ + footer << "\" viewBox=\"0 0 "
    << w << " " << height_ + footer << "\">\n";
}

}  // namespace anisocert::io
