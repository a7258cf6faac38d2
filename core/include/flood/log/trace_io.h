// Saving and loading a Trace (replay.h) as JSON Lines, the file `flood trace` writes and the
// viewer opens. Line 1 is a header:
//   {"format":"flood-trace","version":kTraceFormatVersion,"vertices":[[x,y],...],
//    "rings":[[first,count],...],"parts":[[firstRing,ringCount],...]}
// plus "up":[x,y], the direction the water rose along, when it is not +y,
// then one object per event with the fields of flood::Event its action uses (usesField()) that
// differ from their initial values, always its action (action, side, reason by name; tested
// and passed as lists of test names; fingers as objects; kNone written as null; version 1
// wrote every field, and is still read),
// then a last line {"triangles":[[a,b,c],...],"status":"ok","message":"..."}.
// Coordinates are JSON numbers, or "NaN", "Infinity", "-Infinity" (JSON has none of these;
// an unvalidated run can hold them).
// Loading checks the format and version and every index, and each event against the polygon
// (eventProblem(), events.h); a malformed line becomes a Malformed diagnostic naming the line,
// never a crash.
// The same trace can be written in a compact binary form (`flood trace --format bin`,
// trace_bin.cpp: about 15 bytes an event instead of ~400, and read ~20x faster); the
// readers below take either, told apart by its first bytes ("FLOODTRB").
#pragma once
#include <iosfwd>
#include <string>
#include <string_view>

#include "flood/geometry/status.h"
#include "flood/log/replay.h"

namespace flood {

void writeTrace(std::ostream& out, const Trace& trace);
void writeBinaryTrace(std::ostream& out, const Trace& trace);
constexpr const char* kBinaryTraceMagic = "FLOODTRB";  // the binary form's first bytes
bool isBinaryTrace(std::string_view text);             // starts with them

// Parses a trace, either form; on failure `trace` is left empty and the diagnostic reads
// "NAME:LINE: what is wrong" (JSON Lines) or "NAME: byte B: what is wrong" (binary).
Diagnostic parseTrace(std::string_view text, const std::string& name, Trace& trace);
Diagnostic parseBinaryTrace(std::string_view text, const std::string& name, Trace& trace);
Diagnostic readTraceFile(const std::string& path, Trace& trace);  // "-" reads stdin

}  // namespace flood
