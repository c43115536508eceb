#!/usr/bin/env python3
"""What a Cortex-M firmware image's interrupt handlers may reach: no software double-precision routine, no string
routine.

  interrupt_reach.py --elf <image.elf> --map <image.map> --build-directory <dir> --objdump <arm-none-eabi-objdump>
                     --readelf <arm-none-eabi-readelf> --annotations <file>

The Cortex-M4F's FPU is single precision: a double in an interrupt handler is a call to libgcc's software routines
(__aeabi_dmul, __aeabi_d2uiz, ...: some hundred instructions each), and a string compared at run time (memcmp,
strlen, std::char_traits<char>::compare) is work that a hardware access resolved at compile time does not need
(issue #23). This walks the image's call graph, as worst_case_stack.py builds it from the disassembly (direct calls,
tail calls, and the indirect calls its annotations file describes, the model's tasks included), from every handler of
the vector table, and fails (exit code 1) with each path from a handler to a forbidden routine.

Left out, and why: Reset_Handler, which runs main in thread mode, not an interrupt; and the fault path
(duet_cortex_m_fault_entry and what it calls), which the fault handlers, the unhandled interrupts' Default_Handler and
a failing halt() enter: it masks interrupts, records the fault and stops the firmware for good, so no control loop
runs after it and its cost bounds nothing. Every other handler counts: device interrupts, SysTick, PendSV, SVCall.
"""

import argparse
import pathlib
import re
import sys

import worst_case_stack as stack

FORBIDDEN = [
    # libgcc's double precision: the AEABI names (__aeabi_dadd, __aeabi_d2uiz, __aeabi_i2d, __aeabi_f2d, ...) and the
    # GCC names they alias (__adddf3, __floatsidf, __extendsfdf2, __truncdfsf2, __eqdf2, __unorddf2, ...).
    re.compile(r"__aeabi_(d\w+|\w+2d)"),
    re.compile(r"__\w*df\d?"),
    # String routines, and the library's wrappers of them.
    re.compile(r"(memcmp|strcmp|strncmp|strlen|strnlen)"),
    re.compile(r"std::char_traits<char>::(compare|length)\b.*"),
    re.compile(r"std::(__cxx11::)?basic_string_view<.*>::compare\b.*"),
]


def forbidden(labels):
    return any(pattern.fullmatch(label) for label in labels for pattern in FORBIDDEN)


def paths_to_forbidden(analysis, entry, fault_entry):
    """The shortest path from `entry` to each forbidden routine it reaches (breadth first), the fault path left out."""
    parents = {entry: None}
    queue = [entry]
    found = []
    while queue:
        address = queue.pop(0)
        function = analysis.functions[address]
        labels = function.names + [analysis.label(function)]
        if forbidden(labels):
            path = []
            step = address
            while step is not None:
                path.append(analysis.label(analysis.functions[step]))
                step = parents[step]
            found.append(" -> ".join(reversed(path)))
            continue  # what a forbidden routine calls is its own business
        callees = set(function.calls)
        if function.indirect:
            callees.update(analysis.indirect_targets(function, with_tasks=True))
        for callee in sorted(callees - {fault_entry}):
            if callee not in parents:
                parents[callee] = address
                queue.append(callee)
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    for option in ("--elf", "--map", "--build-directory", "--annotations"):
        parser.add_argument(option, required=True, type=pathlib.Path)
    parser.add_argument("--objdump", required=True)
    parser.add_argument("--readelf", required=True)
    arguments = parser.parse_args()
    try:
        functions, symbols = stack.read_functions(arguments.readelf, arguments.elf)
        stack.read_disassembly(arguments.objdump, arguments.elf, functions)
        stack.resolve_calls(functions)
        stack.read_compiler_stack(arguments.map, arguments.build_directory, functions)
        names = stack.demangle(sorted({name for function in functions.values() for name in function.names}))
        fault_entry = symbols[stack.FAULT_ENTRY] & ~1
        analysis = stack.Analysis(functions, stack.address_taken(arguments.objdump, arguments.elf, functions),
                                  stack.read_annotations(arguments.annotations), {}, names, fault_entry)
        vectors = stack.read_vector_table(arguments.objdump, arguments.elf)
        reset = vectors[1] & ~1
        handlers = sorted({vector & ~1 for vector in vectors[2:] if vector} - {reset, fault_entry})
        problems = []
        for handler in handlers:
            problems.extend(paths_to_forbidden(analysis, handler, fault_entry))
    except stack.AnalysisError as error:
        print(f"interrupt_reach: {arguments.elf.name}: {error}")
        return 1
    if problems:
        print(f"interrupt_reach: {arguments.elf.name}: {len(problems)} paths from an interrupt handler to a software "
              "double-precision or string routine:")
        for path in problems:
            print("  " + path)
        return 1
    print(f"interrupt_reach: {arguments.elf.name}: none of its {len(handlers)} handlers reaches a software "
          "double-precision or string routine")
    return 0


if __name__ == "__main__":
    sys.exit(main())
