#!/usr/bin/env python3
"""The worst-case stack of a Cortex-M firmware image, from the compiler's stack usage and the image's call graph.

  worst_case_stack.py --elf <image.elf> --map <image.map> --build-directory <dir> --objdump <arm-none-eabi-objdump>
                      --readelf <arm-none-eabi-readelf> --annotations <file> [--assume FUNCTION=BYTES]...
                      [--report <file>]

Stack usage per function: the compiler's (-fcallgraph-info=su, the .ci file beside each object the map lists); for
code without one (libgcc, assembly) the pushes and stack adjustments of its disassembly. Call graph: the linked
image's disassembly (bl, blx and branches out of the function: calls and tail calls). Indirect calls: the compiler
reports where each one is (.ci); --annotations (stack_annotations.txt) says, for the call written there, which
functions it may reach, among those whose address the image holds as data (a Thumb address in .text, .data or
.init_array); the bound is the deepest of them. An indirect call that no line describes, recursion and dynamic stack
allocation are errors, unless --assume gives the function's worst case, callees included, or the annotations file
gives a recursion's depth.

Entries: Reset_Handler runs main on the main stack; every other handler of the vector table may preempt it and each
other, each level stacking the extended frame (26 words with the FPU state, plus the alignment word). The NVIC has 16
preemption levels (duet writes 4 priority bits on every board, cortex_m/interrupts.hpp) and a handler preempts only a
more urgent one, so at most 16 handlers are active at once: the bound takes the 16 deepest, a conservative bound that
needs no priorities. A handler counts without the model's tasks (the indirect calls marked "tasks"); the tasks count
apart, each once, since a task runs at its one priority and cannot preempt itself. A fault, or an interrupt nobody
handles (Default_Handler), stacks one more frame on the main stack, masks interrupts and runs on the fault stack
(fault.cpp), which is checked on its own. Fails (exit code 1) when either stack does not fit, when a function takes
so much stack at once that with a fault's frame it could step over the guard below the stack, or when the analysis
cannot bound a path. Prints the worst case with its paths; --report also gets each indirect call's targets.
"""

import argparse
import bisect
import pathlib
import re
import subprocess
import sys

EXTENDED_FRAME = 26 * 4 + 4  # ARMv7-M B1.5.7: FP state included, plus the word that realigns the stack to 8 bytes
PREEMPTION_LEVELS = 16
FAULT_ENTRY = "duet_cortex_m_fault_entry"  # switches to the fault stack (fault.cpp)
FAULT_PATH = "duet_cortex_m_fault"
REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


class AnalysisError(Exception):
    pass


def run(*command):
    return subprocess.run(command, check=True, capture_output=True, text=True).stdout


class Function:
    def __init__(self, name, address, size):
        self.names = [name]
        self.address = address
        self.size = size
        self.calls = set()  # addresses
        self.indirect = False
        self.indirect_sites = set()  # (source file relative to the repository, line number)
        self.disassembled_stack = 0
        self.compiler_stack = None
        self.dynamic = False

    @property
    def name(self):
        return self.names[0]


def read_functions(readelf, elf):
    functions = {}
    symbols = {}
    for line in run(readelf, "--symbols", "--wide", elf).splitlines():
        fields = line.split()
        # Num: Value Size Type Bind Vis Ndx Name
        if len(fields) < 8 or fields[3] not in ("FUNC", "OBJECT", "NOTYPE"):
            continue
        name, value = fields[7], int(fields[1], 16)
        symbols.setdefault(name, value)
        if fields[3] != "FUNC" or fields[6] == "UND":
            continue
        address = value & ~1
        if address in functions:
            functions[address].names.append(name)
        else:
            functions[address] = Function(name, address, int(fields[2], 0))
    # libgcc's assembly declares some functions without a size: each then runs to the next.
    starts = sorted(functions)
    for address, following in zip(starts, starts[1:]):
        if functions[address].size == 0:
            functions[address].size = following - address
    return functions, symbols


REGISTER_LIST = re.compile(r"\{([^}]*)\}")


def register_count(operands):
    count = 0
    for item in REGISTER_LIST.search(operands).group(1).split(","):
        item = item.strip()
        if "-" in item:
            first, last = (int(re.sub(r"\D", "", end)) for end in item.split("-"))
            count += last - first + 1
        elif item:
            count += 1
    return count


def pushed_bytes(mnemonic, operands):
    """Bytes an instruction takes from the stack, for code the compiler did not describe."""
    if mnemonic in ("push", "push.w") or (mnemonic.startswith("stmdb") and operands.startswith("sp!")):
        return 4 * register_count(operands)
    if mnemonic in ("vpush", "vpush.64", "vpush.32", "vstmdb") and ("sp!" in operands or mnemonic.startswith("vpush")):
        return (8 if "{d" in operands else 4) * register_count(operands)
    if mnemonic in ("str", "str.w") and re.search(r"\[sp, #-(\d+)\]!", operands):
        return int(re.search(r"\[sp, #-(\d+)\]!", operands).group(1))
    adjustment = re.fullmatch(r"sp, (?:sp, )?#(\d+)", operands)
    if mnemonic in ("sub", "sub.w", "subw") and adjustment:
        return int(adjustment.group(1))
    return 0


INSTRUCTION = re.compile(r"^\s*([0-9a-f]+):\s+(\S+)\s*(.*?)\s*$")
TARGET = re.compile(r"^([0-9a-f]+)(?: <[^>]*>)?$")


def read_disassembly(objdump, elf, functions):
    starts = sorted(functions)
    ends = {address: address + functions[address].size for address in starts}
    current = None
    for line in run(objdump, "--disassemble", "--no-show-raw-insn", elf).splitlines():
        match = INSTRUCTION.match(line)
        if not match:
            continue
        address = int(match.group(1), 16)
        if current is None or not (current.address <= address < ends[current.address]):
            current = functions.get(address)
            if current is None:
                continue
        mnemonic, operands = match.group(2), match.group(3).split(";")[0].split("@")[0].strip()
        if mnemonic == ".word":
            continue
        current.disassembled_stack += pushed_bytes(mnemonic, operands)
        branch = re.match(r"^(bl|blx|b)(?:eq|ne|cs|cc|mi|pl|vs|vc|hi|ls|ge|lt|gt|le|hs|lo)?(?:\.[nw])?$", mnemonic)
        target = TARGET.match(operands)
        if branch and target:
            destination = int(target.group(1), 16)
            if branch.group(1) != "b" or not (current.address <= destination < ends[current.address]):
                current.calls.add(destination)
        elif mnemonic in ("blx", "bx") and operands != "lr":
            current.indirect = True
        elif re.match(r"^(mov|ldr)(\.w)?$", mnemonic) and operands.startswith("pc,") and "[sp]" not in operands:
            current.indirect = True


def resolve_calls(functions):
    """Each call's target as the function that holds it. libgcc's assembly branches into the middle of its own code
    beyond a symbol's declared size and into its neighbours: such a branch counts the whole function there, and one
    into the function itself is no call."""
    starts = sorted(functions)
    for function in functions.values():
        targets = set()
        for target in function.calls:
            holder = starts[bisect.bisect_right(starts, target) - 1] if target >= starts[0] else None
            if holder is None or target >= holder + functions[holder].size:
                raise AnalysisError(f"{function.name} calls {target:#x}, in no function")
            if holder != function.address or target == function.address:
                targets.add(holder)
        function.calls = targets


def read_compiler_stack(map_file, build, functions):
    """The compiler's figure and indirect calls for each function, from the .ci file beside each object the image
    links. The map names objects relative to the build directory, where the linker ran."""
    objects = set(re.findall(r"(\S+\.obj\)?)(?:\s|$)", map_file.read_text()))
    call_graphs = []
    for name in objects:
        member = re.match(r"(.*)/lib([^/]+)\.a\((.+)\.obj\)$", name)
        if member:  # an archive's member: its object lies under the library's CMakeFiles/<library>.dir
            library = build / member.group(1) / "CMakeFiles" / f"{member.group(2)}.dir"
            call_graphs.extend(library.rglob(member.group(3) + ".ci"))
        else:
            call_graphs.append((build / name).with_suffix(".ci"))
    by_name = {}
    for function in functions.values():
        for name in function.names:
            by_name[name] = function
    node = re.compile(r'node: \{ title: "([^"]+)" label: "[^"]*\\n(\d+) bytes \(([a-z,]+)\)"')
    missing = [str(path) for path in call_graphs if not path.exists()]
    if missing:
        raise AnalysisError("no call graph (-fcallgraph-info=su) for " + ", ".join(sorted(missing)[:5]))
    indirect_edge = re.compile(r'edge: \{ sourcename: "([^"]+)" targetname: "__indirect_call" label: "(.+):(\d+):\d+"')
    for path in call_graphs:
        text = path.read_text()
        for title, size, qualifier in node.findall(text):
            function = by_name.get(title.rpartition(":")[2])  # local and weak functions: "<source>:<name>"
            if function is None:
                continue
            function.compiler_stack = max(function.compiler_stack or 0, int(size))
            function.dynamic |= qualifier == "dynamic"  # "dynamic,bounded" is included in the figure
        for title, source, line in indirect_edge.findall(text):
            function = by_name.get(title.rpartition(":")[2])
            if function is not None:
                source_path = (build / source).resolve().relative_to(REPOSITORY)
                function.indirect_sites.add((source_path.as_posix(), int(line)))


def address_taken(objdump, elf, functions):
    """Functions whose Thumb address the image holds as data: what an indirect call may reach."""
    words = set()
    dump = run(objdump, "--full-contents", "--section=.text", "--section=.data", "--section=.init_array", elf)
    for line in dump.splitlines():
        match = re.match(r"^ ([0-9a-f]+) ((?:[0-9a-f]{8} ?){1,4})", line)
        if not match:
            continue
        base = int(match.group(1), 16)
        if base % 4:
            continue
        for word in match.group(2).split():
            words.add(int.from_bytes(bytes.fromhex(word), "little"))
    return sorted(address for address in functions if (address | 1) in words)


class IndirectCall:
    def __init__(self, source, call, expression, runs_tasks):
        self.source = source
        self.call = call
        self.expression = re.compile(expression)
        self.runs_tasks = runs_tasks


def read_annotations(path):
    """The indirect calls and the recursion depths of the annotations file:
    indirect | <source file> | <call> | <expression> [| tasks]   and   recursion | <function> | <depth>."""
    calls = []
    depths = {}
    for number, line in enumerate(path.read_text().splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        fields = [field.strip() for field in line.split(" | ")]
        if fields[0] == "indirect" and len(fields) in (4, 5) and fields[4:] in ([], ["tasks"]):
            calls.append(IndirectCall(fields[1], fields[2], fields[3], fields[4:] == ["tasks"]))
        elif fields[0] == "recursion" and len(fields) == 3 and fields[2].isdigit():
            depths[fields[1]] = int(fields[2])
        else:
            raise AnalysisError(f"{path}:{number}: neither indirect | <source file> | <call> | <expression> [| tasks] "
                                "nor recursion | <function> | <depth>")
    return calls, depths


def without_parameters(label):
    """A demangled name without its parameter list: "(anonymous namespace)::f(int)" -> "(anonymous namespace)::f"."""
    if not label.endswith(")"):
        return label
    depth = 0
    for index in range(len(label) - 1, -1, -1):
        depth += {")": 1, "(": -1}.get(label[index], 0)
        if depth == 0:
            return label[:index]
    return label


def read_vector_table(objdump, elf):
    entries = []
    for line in run(objdump, "--full-contents", "--section=.vector_table", elf).splitlines():
        match = re.match(r"^ ([0-9a-f]+) ((?:[0-9a-f]{8} ?){1,4})", line)
        if match:
            entries.extend(int.from_bytes(bytes.fromhex(word), "little") for word in match.group(2).split())
    return entries


def demangle(names):
    return dict(zip(names, run("c++filt", *names).splitlines())) if names else {}


class Analysis:
    def __init__(self, functions, address_taken, annotations, assumptions, names, fault_entry):
        self.functions = functions
        self.fault_entry = fault_entry
        self.address_taken = address_taken
        self.indirect_calls, self.recursion_depths = annotations
        self.assumptions = assumptions
        self.names = names
        self.worst = {}
        self.on_path = []
        self.notes = set()
        self.tasks = set()  # the entries of the calls marked "tasks"

    def label(self, function):
        return self.names.get(function.name, function.name)

    def indirect_targets(self, function, with_tasks):
        """The functions an indirect call of `function` may reach; without the tasks when not `with_tasks`."""
        if not function.indirect_sites:
            raise AnalysisError(f"{self.label(function)} calls through a pointer the compiler did not report")
        targets = set()
        for source, line in sorted(function.indirect_sites):
            text = (REPOSITORY / source).read_text().splitlines()[line - 1]
            calls = [call for call in self.indirect_calls if call.source == source and call.call in text]
            if not calls:
                raise AnalysisError(f"the indirect call at {source}:{line} ({text.strip()}) in {self.label(function)}: "
                                    "no line of the annotations file says where it goes")
            reached = {address for address in self.address_taken for call in calls
                       if call.expression.fullmatch(self.label(self.functions[address]))}
            if any(call.runs_tasks for call in calls):
                self.tasks.update(reached)
                if not with_tasks:
                    continue
            self.notes.add(f"indirect call at {source}:{line}: " +
                           (", ".join(sorted(self.label(self.functions[address]) for address in reached))
                            if reached else "no function of the image"))
            targets.update(reached)
        return targets

    def own_stack(self, function):
        return function.compiler_stack if function.compiler_stack is not None else function.disassembled_stack

    def annotated(self, function, table):
        for name in function.names + [self.label(function), without_parameters(self.label(function))]:
            if name in table:
                return table[name]
        return None

    def deepest(self, address, with_tasks=True):
        """(bytes, path) of the deepest stack from the function at `address`, itself included; without the tasks its
        calls marked "tasks" run, when not `with_tasks`."""
        # A function with a recursion depth may be on the path that many times; results depend on how often it is.
        key = (address, with_tasks, tuple(step for step in self.on_path
                                          if self.annotated(self.functions[step], self.recursion_depths)))
        if key in self.worst:
            return self.worst[key]
        if address == self.fault_entry:  # it leaves this stack for the fault stack at once
            return (0, [f"{FAULT_ENTRY} (to the fault stack)"])
        function = self.functions[address]
        bound = self.annotated(function, self.assumptions)
        if bound is not None:
            self.worst[key] = (bound, [f"{self.label(function)} (assumed {bound} B)"])
            return self.worst[key]
        depth = self.annotated(function, self.recursion_depths)
        if depth is not None and self.on_path.count(address) >= depth:
            return (0, [])  # deeper than the annotated depth: no such path
        if address in self.on_path and depth is None:
            cycle = [self.label(self.functions[step]) for step in self.on_path[self.on_path.index(address):]]
            raise AnalysisError("recursion without a bound (--assume): " + " -> ".join(cycle + [cycle[0]]))
        if function.dynamic:
            raise AnalysisError(f"{self.label(function)} allocates a dynamic stack without a bound (--assume)")
        self.on_path.append(address)
        callees = set(function.calls)
        if function.indirect:
            callees.update(self.indirect_targets(function, with_tasks))
        best = (0, [])
        for callee in sorted(callees):
            result = self.deepest(callee, with_tasks)
            if result[0] > best[0]:
                best = result
        self.on_path.pop()
        own = self.own_stack(function)
        source = "" if function.compiler_stack is not None else ", from its disassembly"
        self.worst[key] = (own + best[0], [f"{self.label(function)} ({own} B{source})"] + best[1])
        return self.worst[key]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--elf", required=True, type=pathlib.Path)
    parser.add_argument("--map", required=True, type=pathlib.Path)
    parser.add_argument("--build-directory", required=True, type=pathlib.Path)
    parser.add_argument("--objdump", required=True)
    parser.add_argument("--readelf", required=True)
    parser.add_argument("--annotations", required=True, type=pathlib.Path)
    parser.add_argument("--assume", action="append", default=[], metavar="FUNCTION=BYTES")
    parser.add_argument("--report", type=pathlib.Path)
    arguments = parser.parse_args()
    assumptions = {}
    for assumption in arguments.assume:
        name, _, size = assumption.rpartition("=")
        assumptions[name] = int(size)

    lines = []
    details = []  # in the report file, and on the console when the analysis fails
    try:
        functions, symbols = read_functions(arguments.readelf, arguments.elf)
        read_disassembly(arguments.objdump, arguments.elf, functions)
        resolve_calls(functions)
        read_compiler_stack(arguments.map, arguments.build_directory, functions)
        names = demangle(sorted({function.name for function in functions.values()}))
        fault_entry = symbols[FAULT_ENTRY] & ~1
        analysis = Analysis(functions, address_taken(arguments.objdump, arguments.elf, functions),
                            read_annotations(arguments.annotations), assumptions, names, fault_entry)
        vectors = read_vector_table(arguments.objdump, arguments.elf)
        stack_size = symbols["__stack_end"] - symbols["__stack_limit"]
        guard_size = symbols["__stack_limit"] - symbols["__stack_guard_start"]
        fault_stack_size = symbols["__fault_stack_end"] - symbols["__stack_end"]
        if vectors[0] != symbols["__stack_end"]:
            raise AnalysisError(f"the initial stack pointer {vectors[0]:#x} is not the stack's top __stack_end")

        reset = vectors[1] & ~1
        handlers = {vector & ~1 for vector in vectors[2:] if vector} - {reset, fault_entry}
        # A line nobody handles goes straight to the fault path, which masks interrupts and never returns: like a
        # fault, it stacks one frame (counted below) and nothing nests on it.
        unhandled = {handler for handler in handlers if functions[handler].calls == {fault_entry}
                     and analysis.own_stack(functions[handler]) == 0 and not functions[handler].indirect}
        handlers = sorted(handlers - unhandled)
        thread = analysis.deepest(reset)
        # Each handler without the tasks it runs, then the tasks apart: a task runs at its one priority, so it is
        # active at most once however deep the nesting.
        nested = sorted(((analysis.deepest(handler, with_tasks=False)[0] + EXTENDED_FRAME, handler)
                         for handler in handlers), reverse=True)[:PREEMPTION_LEVELS]
        tasks = sorted(((analysis.deepest(task)[0], task) for task in analysis.tasks),
                       reverse=True)[:PREEMPTION_LEVELS]
        fault_path = analysis.deepest(symbols[FAULT_PATH] & ~1)
        main_stack = (thread[0] + sum(size for size, _ in nested) + sum(size for size, _ in tasks)
                      + EXTENDED_FRAME)  # the fault's own frame
        fault_stack = fault_path[0] + EXTENDED_FRAME  # an NMI taken in a fault handler stacks on the fault stack

        lines.append(f"worst-case stack of {arguments.elf.name}: {main_stack} B of {stack_size} B reserved "
                     f"(margin {stack_size - main_stack} B); fault stack {fault_stack} B of {fault_stack_size} B")
        lines.append(f"  thread mode from Reset_Handler: {thread[0]} B: " + " -> ".join(thread[1]))
        lines.append(f"  {len(nested)} nested handlers (the deepest of {len(handlers)}, at most "
                     f"{PREEMPTION_LEVELS} preemption levels), each with its {EXTENDED_FRAME} B frame, without the "
                     "tasks they run:")
        for size, handler in nested:
            lines.append(f"    {size} B: " + " -> ".join(analysis.deepest(handler, with_tasks=False)[1]))
        lines.append(f"  {len(tasks)} tasks, each active at most once:")
        for size, task in tasks:
            lines.append(f"    {size} B: " + " -> ".join(analysis.deepest(task)[1]))
        lines.append(f"  a fault's frame, or an unhandled interrupt's ({len(unhandled)} lines): {EXTENDED_FRAME} B")
        lines.append(f"  fault stack: {fault_stack} B ({EXTENDED_FRAME} B of it an NMI's frame): "
                     + " -> ".join(fault_path[1]))
        details = ["  " + note for note in sorted(analysis.notes)]
        analysed = {key[0] for key in analysis.worst}
        estimated = sorted(analysis.label(functions[address]) for address in analysed
                           if functions[address].compiler_stack is None)
        if estimated:
            details.append("  stack from the disassembly (no compiler figure): " + ", ".join(estimated))
        largest = max((analysis.own_stack(functions[address]), analysis.label(functions[address]))
                      for address in analysed)
        lines.append(f"  largest frame: {largest[0]} B ({largest[1]}); the guard is {guard_size} B")

        problems = []
        if main_stack > stack_size:
            problems.append(f"the worst case, {main_stack} B, does not fit the {stack_size} B stack")
        if fault_stack > fault_stack_size:
            problems.append(f"the fault path, {fault_stack} B, does not fit the {fault_stack_size} B fault stack")
        if largest[0] + EXTENDED_FRAME > guard_size:
            problems.append(f"{largest[1]} takes {largest[0]} B at once: with a fault's frame more than the "
                            f"{guard_size} B guard, it could step over it")
        if problems:
            raise AnalysisError("; ".join(problems))
        status = 0
    except AnalysisError as error:
        details.append(f"worst_case_stack: {arguments.elf.name}: {error}")
        status = 1
    if arguments.report:  # only when the stack fits: the build runs the analysis until it makes its report
        arguments.report.unlink(missing_ok=True)
        if status == 0:
            arguments.report.write_text("\n".join(lines + details) + "\n")
    print("\n".join(lines + details if status else lines))
    return status


if __name__ == "__main__":
    sys.exit(main())
