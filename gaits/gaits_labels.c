/* gaits_labels.c: the 96-label map (see gaits_labels.h). */
#include "gaits_labels.h"

#include <stdio.h>
#include <string.h>

/* labels per leg and per segment, from label = 12 k + 4 (s - 1) + j */
#define LABELS_PER_LEG (CSG_NSEG * CSG_NCHAMBER)
#define LABELS_PER_SEG CSG_NCHAMBER


int csg_labelFromTriple(int leg, int seg, int chamber) {
  if (leg < 0 || leg >= CSG_NLEG || seg < 1 || seg > CSG_NSEG || chamber < 1 ||
      chamber > CSG_NCHAMBER) {
    return 0;
  }
  return LABELS_PER_LEG * leg + LABELS_PER_SEG * (seg - 1) + chamber;
}


csStatus csg_labelToTriple(int label, int* leg, int* seg, int* chamber) {
  if (label < 1 || label > CSG_NLABEL) {
    return CS_ERR_RANGE;
  }
  /* 0-based index splits as (leg, seg-1, chamber-1) in mixed radix (8, 3, 4) */
  int i = label - 1;
  if (leg) {
    *leg = i / LABELS_PER_LEG;
  }
  if (seg) {
    *seg = (i % LABELS_PER_LEG) / LABELS_PER_SEG + 1;
  }
  if (chamber) {
    *chamber = i % LABELS_PER_SEG + 1;
  }
  return CS_OK;
}


csStatus csg_labelName(int label, char* buf, size_t size) {
  if (!buf || size == 0) {
    return CS_ERR_ARG;
  }
  buf[0] = '\0';
  int leg, seg, chamber;
  if (csg_labelToTriple(label, &leg, &seg, &chamber) != CS_OK) {
    return CS_ERR_RANGE;
  }
  int n = snprintf(buf, size, "%c_II%d_O%d", 'A' + leg, seg, chamber);
  if (n < 0 || (size_t)n >= size) {
    buf[0] = '\0';
    return CS_ERR_ARG;
  }
  return CS_OK;
}


int csg_labelParse(const char* text) {
  if (!text || !text[0]) {
    return 0;
  }

  /* bare label number: digits only; stop counting early so "000...0001" cannot overflow */
  if (text[0] >= '0' && text[0] <= '9') {
    int v = 0;
    for (const char* c = text; *c; c++) {
      if (*c < '0' || *c > '9') {
        return 0;
      }
      v = 10 * v + (*c - '0');
      if (v > CSG_NLABEL) {
        return 0;
      }
    }
    return v; /* 0 ("0", "00") is no label */
  }

  /* chamber name: exactly 8 chars <A..H>_II<1..3>_O<1..4>; the digits are range-checked by
   * csg_labelFromTriple */
  if (strlen(text) != 8 || text[0] < 'A' || text[0] >= 'A' + CSG_NLEG || text[1] != '_' ||
      text[2] != 'I' || text[3] != 'I' || text[5] != '_' || text[6] != 'O') {
    return 0;
  }
  return csg_labelFromTriple(text[0] - 'A', text[4] - '0', text[7] - '0');
}
