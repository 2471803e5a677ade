/* fields_stones.h - the state fields of the stones system(s), an X-macro table appended to
 * WW_STATE_FIELDS (sim/state.h): X(type, name, count, comment), count 0 when the scene does not
 * have the system. */
#ifndef WW_FIELDS_STONES_H
#define WW_FIELDS_STONES_H

#define WW_FIELDS_STONES(X)

#endif
