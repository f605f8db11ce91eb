/* cs_bendfile.h: read the rows of a `crawlsim bend` output file in a test (header-only, plain C
 * on HDF5's high-level API; shared by test_rod_bend_cli and test_strain_bend_cli). */
#ifndef CS_TEST_BENDFILE_H
#define CS_TEST_BENDFILE_H

#include <hdf5.h>
#include <hdf5_hl.h>

/* the rows of a bend file: pressure (m), angles (m x 3), tip (m x 3), at most maxrow of them;
 * returns m (0 when the file cannot be read or holds more rows) */
static inline int cs_bendFileRead(const char* path, int maxrow, double* p, double* ang,
                                  double* tip) {
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    return 0;
  }
  hsize_t dims[2] = {0, 0};
  H5T_class_t cls;
  size_t ts;
  int m = 0;
  if (H5LTget_dataset_info(f, "/pressure", dims, &cls, &ts) >= 0 && dims[0] <= (hsize_t)maxrow &&
      H5LTread_dataset_double(f, "/pressure", p) >= 0 &&
      H5LTread_dataset_double(f, "/angle_deg", ang) >= 0 &&
      H5LTread_dataset_double(f, "/tip_position", tip) >= 0) {
    m = (int)dims[0];
  }
  H5Fclose(f);
  return m;
}

#endif /* CS_TEST_BENDFILE_H */
