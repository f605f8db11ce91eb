/* placeholder */
typedef int cs_gaits_placeholder_;
