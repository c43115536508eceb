#pragma once
// A Simulink model as its file says it, whatever the container (.slx of each layout era, classic .mdl, the packaged
// text .mdl): systems of blocks and lines, every parameter as the text stored, nothing evaluated, no default filled
// in. The readers fill it; the importer (later) gives it meaning. docs/IMPORT.md describes the formats.

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace duet::simulink_import {

// One end of a line: a block of the same system and a port of it. `kind` is the file's word: "in", "out", "enable",
// "trigger", "ifaction", "Reset", "state", "lconn", "rconn".
struct Endpoint {
  std::string block;  // the block's name in its system (classic .mdl names blocks; .slx SIDs are resolved to names)
  std::string kind;
  int port = 1;  // 1-based
};

// A line with its branches flattened: one source, every destination the branches end at.
struct Line {
  std::string name;  // the signal's name, or empty
  std::optional<Endpoint> source;
  std::vector<Endpoint> destinations;
};

struct System;

// `parameters` holds every <P Name="..."> (.slx) or "Name value" pair (.mdl) of the block as stored, chunked strings
// joined and escapes resolved; an .slx's <PortCounts in="2" out="1"/> is stored as "PortCounts" = "[2, 1]" beside
// the older "Ports" = "[2, 1]", both as written.
struct Block {
  std::string type;                                    // BlockType: "Gain", "SubSystem", "Reference", ...
  std::string name;                                    // unique within its system; may hold newlines
  std::string sid;                                     // empty in files that have none
  std::map<std::string, std::string> parameters;       // <P Name=...> / "Name value", as stored
  std::map<std::string, std::string> mask_parameters;  // a masked block's or a library link's values (InstanceData)
  std::vector<System> systems;                         // a subsystem's contents: one, or none
  std::map<int, std::string> output_names;             // signal names given on output ports (1-based)
  int line = 0;                                        // where the block starts in its part or file, for messages
};

struct System {
  std::vector<Block> blocks;
  std::vector<Line> lines;
  std::string part;  // where it was read from: "simulink/systems/system_3.xml", or the .mdl file
};

// The configuration the importer needs: the active configuration set's solver settings, as stored.
struct Solver {
  std::map<std::string, std::string> parameters;  // "SolverName", "FixedStep", "EnableMultiTasking", ...
};

struct SimulinkModel {
  std::string name;
  std::string release;  // "R2022a" from the .slx metadata or the packaged .mdl's banner; empty when unknown
  std::string format;   // "slx (blockdiagram.xml)", "slx (systems/)", "mdl (classic)", "mdl (packaged text)"
  System root;
  Solver solver;
  // BlockParameterDefaults where the file has them (up to R2021b): BlockType -> parameter -> value.
  std::map<std::string, std::map<std::string, std::string>> defaults;
};

}  // namespace duet::simulink_import
