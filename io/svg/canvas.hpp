#pragma once
// The frame every picture shares: the domain's bounding box, with a margin, scaled so that its
// larger side spans 800 px, y pointing up, and a footer band for captions.
#include "geometry/polygon.hpp"

#include <ostream>
#include <string>

namespace anisocert::io {

// Text for an SVG element's content: &, < and > escaped (a caption names the user's file).
std::string xml_text(const std::string& s);

class Canvas {
 public:
  // `margin`: a fraction of the box's larger side added on every side.
  Canvas(const geometry::Polygon<double>& frame, double margin);
  double X(double x) const { return (x - x0_ + margin_) * px_; }
  double Y(double y) const { return (y1_ - y + margin_) * px_; }
  double scale() const { return px_; }      // pixels per unit
  double size() const { return size_; }     // the box's larger side, in units
  double height() const { return height_; }  // without the footer
  // <svg …> of the frame with a footer band of `footer` px, at least min_width px wide (numbers
  // in the stream's precision).
  void open(std::ostream& o, double footer, double min_width = 0) const;

 private:
  double x0_, x1_, y0_, y1_, size_, margin_, px_, width_, height_;
};

}  // namespace anisocert::io
