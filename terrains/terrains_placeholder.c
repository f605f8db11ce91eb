/* placeholder */
typedef int cs_terrains_placeholder_;
