#include "render_controls.h"

namespace voxray {

RenderControls renderControlsFor(const RenderParams& p) {
  RenderControls c;
  if (p.lighting == Lighting::Cinematic) {
    // cinematicFrame: the path tracer renders dvr from the mode's colour table, with an
    // isotropic phase function (no gradient).
    switch (p.mode) {
      case Mode::Dvr:
        c.note =
            "Cinematic lighting path-traces the volume, scattering light evenly in all "
            "directions: the gradient does not apply.";
        break;
      case Mode::Iso:
        c.note =
            "Cinematic lighting path-traces the volume as dvr with the iso preset's colour "
            "table (without one: CT-Bone's), not the iso surface: the iso range and the "
            "gradient do not apply. Phong, shadows or ao show the iso surface.";
        break;
      case Mode::Mip:
        c.note =
            "Cinematic lighting path-traces the volume as dvr with CT-Bone's colour table (MIP "
            "presets have none), not a maximum intensity projection: the MIP window and the "
            "gradient do not apply. Phong shows the MIP.";
        break;
    }
    return c;
  }
  c.isoRange = p.mode == Mode::Iso;
  c.mipWindow = p.mode == Mode::Mip;
  c.gradient = p.mode != Mode::Mip;  // MIP takes each ray's largest value: nothing is shaded
  return c;
}

}  // namespace voxray
