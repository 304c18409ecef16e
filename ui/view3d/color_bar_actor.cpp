#include "view3d/color_bar_actor.hpp"

#include <algorithm>

#include <vtkCoordinate.h>
#include <vtkObjectFactory.h>
#include <vtkScalarBarActorInternal.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkViewport.h>

namespace maris::ui {

vtkStandardNewMacro(ColorBarActor);

void ColorBarActor::ConfigureTicks() {
  vtkScalarBarActor::ConfigureTicks();  // visibility of each label, its text properties
  labels_.clear();
  // Positions of the strip and of the labels are relative to the bar's own origin (the labels' coordinates take
  // it as their reference); the boxes reported are in viewport pixels.
  int* origin = GetPositionCoordinate()->GetComputedViewportValue(P->Viewport);
  const vtkScalarBarBox& bar = P->ScalarBarBox;
  strip_ = {origin[0] + static_cast<double>(bar.Posn[0]), origin[1] + static_cast<double>(bar.Posn[1]),
            static_cast<double>(bar.Size[0]), static_cast<double>(bar.Size[1])};
  if (Orientation != VTK_ORIENT_VERTICAL || TextPosition != SucceedScalarBar) return;

  struct Placed {
    vtkTextActor* actor;
    PixelBox box;
  };
  std::vector<Placed> placed;
  const double x = bar.Posn[0] + bar.Size[0] + kLabelGap;
  for (int i = 0; i < NumberOfLabelsBuilt; ++i) {
    vtkTextActor* actor = P->TextActors[i];
    const double anchor = P->TextActorAnchors[i];
    if (!(anchor > -1e-6 && anchor < 1 + 1e-6)) continue;  // a tick outside the range (VTK hid it)
    double size[2] = {0, 0};
    actor->GetSize(P->Viewport, size);
    actor->GetTextProperty()->SetJustificationToLeft();
    actor->GetTextProperty()->SetVerticalJustificationToBottom();
    // Centred on its colour: the strip, not VTK's tick box (a few pixels shorter), is where the colours are.
    const double y = bar.Posn[1] + anchor * bar.Size[1] - 0.5 * size[1];
    actor->SetPosition(x, y);
    placed.push_back({actor, {x, y, size[0], size[1]}});
  }
  std::sort(placed.begin(), placed.end(), [](const Placed& a, const Placed& b) { return a.box.bottom < b.box.bottom; });

  // What stays: the lowest, then the highest where it clears the lowest and the title, then every label in
  // between that clears the last one kept below it and the highest.
  const bool has_title = GetTitle() && *GetTitle();
  const double ceiling = has_title ? P->TitleBox.Posn[1] - kLabelGap : 1e300;
  std::vector<bool> keep(placed.size(), false);
  if (!placed.empty()) {
    keep.front() = true;
    const std::size_t top = placed.size() - 1;
    if (top > 0 && placed[top].box.bottom >= placed[0].box.top() + kLabelGap && placed[top].box.top() <= ceiling)
      keep[top] = true;
    const double upper = keep[top] && top > 0 ? placed[top].box.bottom - kLabelGap : ceiling;
    double below = placed[0].box.top() + kLabelGap;
    for (std::size_t i = 1; i < top; ++i)
      if (placed[i].box.bottom >= below && placed[i].box.top() <= upper) {
        keep[i] = true;
        below = placed[i].box.top() + kLabelGap;
      }
  }
  for (std::size_t i = 0; i < placed.size(); ++i) {
    placed[i].actor->SetVisibility(keep[i]);
    if (!keep[i]) continue;
    PixelBox box = placed[i].box;
    box.left += origin[0];
    box.bottom += origin[1];
    labels_.push_back(box);
  }
}

}  // namespace maris::ui
