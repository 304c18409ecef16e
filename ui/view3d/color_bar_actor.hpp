// The colour bar of the 3D view: VTK's scalar bar with its tick labels placed by us. VTK 9.1 right-aligns the
// labels in a column measured before their final text is known, so a longer label ("-500" beside "500") ran into
// the colour strip, and at small sizes neighbouring labels overlapped. Here every label starts a fixed gap right of
// the strip, is centred on the colour it names, and labels that would come nearer than that gap to one another
// (or to the title above) are not drawn: the lowest and the highest are kept first, then every one that fits.
#pragma once

#include <vector>

#include <vtkScalarBarActor.h>

namespace maris::ui {

class ColorBarActor : public vtkScalarBarActor {
 public:
  static ColorBarActor* New();
  vtkTypeMacro(ColorBarActor, vtkScalarBarActor);

  // A rectangle in pixels of the viewport, from its lower-left corner.
  struct PixelBox {
    double left = 0, bottom = 0, width = 0, height = 0;
    double right() const { return left + width; }
    double top() const { return bottom + height; }
  };
  // As last laid out: the colour strip and the labels drawn beside it (hidden ones are left out), bottom to top.
  PixelBox stripBox() const { return strip_; }
  const std::vector<PixelBox>& labelBoxes() const { return labels_; }

  // The clear space between the strip and a label, and between two labels, in pixels.
  static constexpr double kLabelGap = 6.0;

 protected:
  ColorBarActor() = default;
  void ConfigureTicks() override;

 private:
  PixelBox strip_;
  std::vector<PixelBox> labels_;
};

}  // namespace maris::ui
