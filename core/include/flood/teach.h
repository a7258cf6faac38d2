// Flood's teaching layer in one include: what the viewer and `flood transcript` say about a
// run, as data a program can show its own way (docs/LIBRARY.md). Builds on <flood/flood.h>.
#pragma once
#include "flood/flood.h"
#include "flood/machine/vertex_class.h"  // the vertex classes of Fig. 1
#include "flood/teach/decision_tree.h"   // Fig. 9, the decision tree, as data
#include "flood/teach/describe.h"        // an event in one line
#include "flood/teach/inspect.h"         // one event's Fig. 9 tests recomputed, exactly
#include "flood/teach/narrate.h"         // one sentence per event, with the vertices it names
#include "flood/teach/state_table.h"     // Fig. 10, vertex combinations and states
#include "flood/teach/todo_list.h"       // the pending and held gorges at a step
#include "flood/teach/transcript.h"      // the paper's transcript (Fig. 7)
