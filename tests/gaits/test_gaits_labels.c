/* test_gaits_labels.c: the 96-label map (gaits_labels.h): the paper's checks, the round trips
 * label -> name -> label and label -> triple -> label over all 96, and the parser's rejects. */
#include <stdio.h>
#include <string.h>

#include "cs_test.h"
#include "gaits_labels.h"


/* the four checks docs/reference.md quotes from the paper */
static void test_paperChecks(void) {
  static const struct {
    int label, leg, seg, chamber;
    const char* name;
  } kChecks[] = {
      {22, 1, 3, 2, "B_II3_O2"}, /* B-II3-Ω2 */
      {91, 7, 2, 3, "H_II2_O3"}, /* H-II2-Ω3 */
      {28, 2, 1, 4, "C_II1_O4"}, /* C-II1-Ω4 */
      {70, 5, 3, 2, "F_II3_O2"}, /* F-II3-Ω2 */
  };
  for (size_t i = 0; i < sizeof kChecks / sizeof kChecks[0]; i++) {
    CS_EXPECT(csg_labelFromTriple(kChecks[i].leg, kChecks[i].seg, kChecks[i].chamber) ==
              kChecks[i].label);
    int leg = -1, seg = -1, chamber = -1;
    CS_EXPECT(csg_labelToTriple(kChecks[i].label, &leg, &seg, &chamber) == CS_OK);
    CS_EXPECT(leg == kChecks[i].leg && seg == kChecks[i].seg && chamber == kChecks[i].chamber);
    char name[CSG_LABEL_NAME_SIZE];
    CS_EXPECT(csg_labelName(kChecks[i].label, name, sizeof name) == CS_OK);
    CS_EXPECT(!strcmp(name, kChecks[i].name));
    CS_EXPECT(csg_labelParse(kChecks[i].name) == kChecks[i].label);
  }
}


/* every label survives label -> name -> label and label -> triple -> label, and the names are
 * distinct and in label order A_II1_O1 .. H_II3_O4 */
static void test_roundTripAll(void) {
  char prev[CSG_LABEL_NAME_SIZE] = "";
  for (int l = 1; l <= CSG_NLABEL; l++) {
    char name[CSG_LABEL_NAME_SIZE];
    CS_EXPECT(csg_labelName(l, name, sizeof name) == CS_OK);
    CS_EXPECT(strlen(name) == 8);
    CS_EXPECT(csg_labelParse(name) == l);
    CS_EXPECT(strcmp(prev, name) < 0);
    strcpy(prev, name);

    char num[8];
    snprintf(num, sizeof num, "%d", l);
    CS_EXPECT(csg_labelParse(num) == l);

    int leg, seg, chamber;
    CS_EXPECT(csg_labelToTriple(l, &leg, &seg, &chamber) == CS_OK);
    CS_EXPECT(leg >= 0 && leg < CSG_NLEG && seg >= 1 && seg <= CSG_NSEG && chamber >= 1 &&
              chamber <= CSG_NCHAMBER);
    CS_EXPECT(csg_labelFromTriple(leg, seg, chamber) == l);
    CS_EXPECT(l == 12 * leg + 4 * (seg - 1) + chamber);
  }
  char name[CSG_LABEL_NAME_SIZE];
  CS_EXPECT(csg_labelName(1, name, sizeof name) == CS_OK && !strcmp(name, "A_II1_O1"));
  CS_EXPECT(csg_labelName(96, name, sizeof name) == CS_OK && !strcmp(name, "H_II3_O4"));
}


/* out-of-range triples and labels, small buffers */
static void test_ranges(void) {
  CS_EXPECT(csg_labelFromTriple(-1, 1, 1) == 0);
  CS_EXPECT(csg_labelFromTriple(8, 1, 1) == 0);
  CS_EXPECT(csg_labelFromTriple(0, 0, 1) == 0);
  CS_EXPECT(csg_labelFromTriple(0, 4, 1) == 0);
  CS_EXPECT(csg_labelFromTriple(0, 1, 0) == 0);
  CS_EXPECT(csg_labelFromTriple(0, 1, 5) == 0);
  int leg = 42;
  CS_EXPECT(csg_labelToTriple(0, &leg, NULL, NULL) == CS_ERR_RANGE);
  CS_EXPECT(csg_labelToTriple(97, &leg, NULL, NULL) == CS_ERR_RANGE);
  CS_EXPECT(leg == 42); /* untouched on failure */
  CS_EXPECT(csg_labelToTriple(96, NULL, NULL, NULL) == CS_OK);
  char name[CSG_LABEL_NAME_SIZE];
  CS_EXPECT(csg_labelName(0, name, sizeof name) == CS_ERR_RANGE && name[0] == '\0');
  CS_EXPECT(csg_labelName(97, name, sizeof name) == CS_ERR_RANGE);
  char small[8]; /* one short of "A_II1_O1" + NUL */
  CS_EXPECT(csg_labelName(1, small, sizeof small) == CS_ERR_ARG && small[0] == '\0');
  CS_EXPECT(csg_labelName(1, NULL, 16) == CS_ERR_ARG);
}


/* the parser accepts exactly the two forms and nothing near them */
static void test_parseRejects(void) {
  static const char* const kBad[] = {
      "",         "0",         "00",       "97",
      "100",      "-1",        "+5",       " 5",
      "5 ",       "5a",        "1.0",      "a_II1_O1",
      "I_II1_O1", "A_II0_O1",  "A_II4_O1", "A_II1_O0",
      "A_II1_O5", "A_II1_O1x", "A_II1_O",  "A_II",
      "A",        "A-II1-O1",  "A_III_O1", "A_II1_o1",
      "AxII1_O1", "A_II1_01",  "time",     "99999999999999999999",
  };
  for (size_t i = 0; i < sizeof kBad / sizeof kBad[0]; i++) {
    if (csg_labelParse(kBad[i]) != 0) {
      fprintf(stderr, "accepted '%s'\n", kBad[i]);
      CS_EXPECT(0);
    }
  }
  CS_EXPECT(csg_labelParse(NULL) == 0);
  CS_EXPECT(csg_labelParse("096") == 96); /* leading zeros are still the number */
  CS_EXPECT(csg_labelParse("H_II3_O4") == 96);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_paperChecks);
  CS_RUN(test_roundTripAll);
  CS_RUN(test_ranges);
  CS_RUN(test_parseRejects);
  return cs_testSummary();
}
