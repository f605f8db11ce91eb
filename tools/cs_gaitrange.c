/* cs_gaitrange.c: a gait against a calibration's pressure range (see cs_gaitrange.h). */
#include "cs_gaitrange.h"

#include <math.h>

#include "gaits_labels.h"
#include "robot_calibration_model.h"

/* the calibration model's own slack above its last row (robot_calibration_internal.h) */
static const double kRangeTol = 1e-12;


csStatus csx_gaitRangeCheck(const csgGait* g, const char* gait_path, double scale,
                            const csrCalibration* cal, int stiffness, csError* err) {
  const csrBendMap map = csr_calibrationMap(cal);
  const csrCalModel* model = csr_calibrationModel(cal);
  const double k_pmax = model && stiffness ? csr_calModelStiffnessPMax(model) : NAN;
  for (int r = 0; r < g->nrow; r++) {
    const double* p = &g->pressure[(size_t)CSG_NLABEL * r];
    for (int s0 = 0; s0 < CSG_NLABEL; s0 += CSG_NCHAMBER) { /* one segment: 4 chambers */
      double mean = 0;
      for (int j = 0; j < CSG_NCHAMBER; j++) {
        const double pj = p[s0 + j] * scale;
        mean += 0.25 * pj;
        if (pj > map.p_max + kRangeTol) {
          char name[CSG_LABEL_NAME_SIZE];
          csg_labelName(s0 + j + 1, name, sizeof name);
          return cs_errorSet(err, CS_ERR_RANGE, "%s: row at t = %g s: chamber %s at %g MPa is "
                             "above the calibrated range (up to %g MPa) of %s", gait_path,
                             g->time[r], name, pj, map.p_max, map.name);
        }
      }
      if (!isnan(k_pmax) && mean > k_pmax + kRangeTol) {
        char name[CSG_LABEL_NAME_SIZE];
        csg_labelName(s0 + 1, name, sizeof name);
        return cs_errorSet(err, CS_ERR_RANGE, "%s: row at t = %g s: the segment of %s has a mean "
                           "chamber pressure of %g MPa, above the range of the calibration's "
                           "stiffness probes (up to %g MPa) of %s (rod legs; --cal-drop "
                           "stiffness leaves them out)", gait_path, g->time[r], name, mean,
                           k_pmax, map.name);
      }
    }
  }
  return CS_OK;
}
