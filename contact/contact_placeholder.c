/* placeholder */
typedef int cs_contact_placeholder_;
