/* gaits_labels.h: the 96-label map of the robot's chambers.
 *
 * Owns: the numbering label = 12 k + 4 (s - 1) + j (docs/reference.md "The robot"), with leg
 * k = 0..7 for A..H, segment s = 1..3 (II1 at the base, II3 the foot) and chamber j = 1..4
 * (Ω1..Ω4); its inverse; the chamber names used as gait CSV column names, "A_II1_O1" ..
 * "H_II3_O4" (leg letter, II<s>, O<j>; 'O' stands for Ω so names stay ASCII); and parsing a
 * column name given either as such a name or as a bare label number "1".."96".
 *
 * It lives in gaits/ (not robot/) because the gait reader must parse column names and gaits/
 * depends on nothing of ours; robot/ uses it from here. Paper checks: 22 = B-II3-Ω2,
 * 91 = H-II2-Ω3, 28 = C-II1-Ω4, 70 = F-II3-Ω2. Labels are 1-based and 0 means "no label"
 * (docs/style.md 10: zero is null). All functions are pure: no state, no allocation. */
#ifndef CS_GAITS_LABELS_H
#define CS_GAITS_LABELS_H

#include <stddef.h>

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CSG_NLEG 8                                      /* legs A..H */
#define CSG_NSEG 3                                      /* segments II1..II3 per leg */
#define CSG_NCHAMBER 4                                  /* chambers Ω1..Ω4 per segment */
#define CSG_NLABEL (CSG_NLEG * CSG_NSEG * CSG_NCHAMBER) /* 96 chambers, labels 1..96 */
#define CSG_LABEL_NAME_SIZE 16 /* buffer size for a name: "A_II1_O1" is 8 chars + NUL */

/* Label of (leg, seg, chamber): leg 0..7 (A..H), seg 1..3, chamber 1..4 -> 1..96.
 * Returns 0 if any index is out of range. */
int csg_labelFromTriple(int leg, int seg, int chamber);

/* Inverse of csg_labelFromTriple: label 1..96 -> leg 0..7, seg 1..3, chamber 1..4. Any output
 * pointer may be NULL. Returns CS_OK, or CS_ERR_RANGE (outputs untouched) for a label outside
 * 1..96. */
csStatus csg_labelToTriple(int label, int* leg, int* seg, int* chamber);

/* Write the chamber name of `label` ("B_II3_O2" for 22) into buf (`size` bytes, at least
 * CSG_LABEL_NAME_SIZE is always enough). Returns CS_OK; CS_ERR_RANGE for a label outside
 * 1..96 or CS_ERR_ARG for a NULL or too small buffer (then buf, if size > 0, holds ""). */
csStatus csg_labelName(int label, char* buf, size_t size);

/* Parse a column name: a chamber name exactly as csg_labelName writes it ("A_II1_O3",
 * case-sensitive) or a bare decimal label number "1".."96" (digits only, no sign, no spaces;
 * the caller trims). Returns the label 1..96, or 0 if `text` is neither (or NULL). */
int csg_labelParse(const char* text);

#ifdef __cplusplus
}
#endif
#endif /* CS_GAITS_LABELS_H */
