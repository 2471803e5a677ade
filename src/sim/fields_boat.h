/* fields_boat.h - the state fields of the boat system(s), an X-macro table appended to
 * WW_STATE_FIELDS (sim/state.h): X(type, name, count, comment), count 0 when the scene does not
 * have the system. */
#ifndef WW_FIELDS_BOAT_H
#define WW_FIELDS_BOAT_H

#define WW_FIELDS_BOAT(X)

#endif
