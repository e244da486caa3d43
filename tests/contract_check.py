#!/usr/bin/env python3
"""Checks that the shaders agree with common/base/include/t10/contract.hpp (the host/shader interface).

usage: contract_check.py CONTRACT_HPP SHADER_DIR...

Reads the constants of contract.hpp and, in every shader of the given folders, checks
- the InvResolution block's binding, and the texture unit of each post-process sampler
  (s2AccumulationTexture, s2LuminanceKeyTexture, s2BloomTexture, s2InputTexture = the bloom unit);
- the uniform locations of extras' settings (fYwhite, fBloomThreshold, fBloomStrength,
  bRangeMapping, bBloom);
- the tutorial's literals where a shader writes them: the Rec. 709 weights, epsilon, Yw, the bloom
  threshold factor and weight, sigma and the two tap offsets.
Prints each disagreement with its file and line and exits 1 if there is any.
"""
import pathlib
import re
import sys

CONSTANT = re.compile(r"constexpr\s+\w+\s+(k\w+)\s*=\s*([0-9.e+-]+)\s*;")
BINDING = re.compile(r"layout\s*\(\s*binding\s*=\s*(\d+)\s*\)\s*uniform\s+(\w+)(?:\s+(\w+))?")
LOCATION = re.compile(r"layout\s*\(\s*location\s*=\s*(\d+)\s*\)\s*uniform\s+\w+\s+(\w+)")
SAMPLER_UNIT = {"s2AccumulationTexture": "kAccumulationUnit", "s2LuminanceKeyTexture": "kLuminanceKeyUnit",
                "s2BloomTexture": "kBloomUnit", "s2InputTexture": "kBloomUnit"}
UNIFORM_LOCATION = {
    ("PostProcess.frag", "fYwhite"): "kWhitePointLocation",
    ("PostProcessInit.frag", "fYwhite"): "kWhitePointLocation",
    ("PostProcess.frag", "bRangeMapping"): "kRangeMappingLocation",
    ("PostProcessInit.frag", "bRangeMapping"): "kRangeMappingLocation",
    ("PostProcessInit.frag", "fBloomThreshold"): "kBloomThresholdLocation",
    ("PostProcess.frag", "fBloomStrength"): "kBloomStrengthLocation",
    ("PostProcess.frag", "bBloom"): "kBloomSwitchLocation",
}
# Literal patterns of the tutorial's code: (regex with one number group per constant, constants).
LITERALS = [
    (r"vec3\(([0-9.]+)f,\s*([0-9.]+)f,\s*([0-9.]+)f\)", ("kLumaRed", "kLumaGreen", "kLumaBlue"), "v3LuminanceConvert"),
    (r"fEpsilon\s*=\s*([0-9.]+)f", ("kEpsilon",), None),
    (r"const float fYwhite\s*=\s*([0-9.]+)f", ("kWhitePoint",), None),
    (r"fYwhite \* ([0-9.]+)f", ("kBloomThresholdFactor",), None),
    (r"v3Bloom \* ([0-9.]+)f", ("kBloomWeight",), None),
    (r"fGaussSigma\s*=\s*([0-9.]+)f", ("kGaussSigma",), None),
    (r"v2Du1 = vec2\(([0-9.]+)f \*", ("kInnerTap",), None),
    (r"return vec2\(([0-9.]+)f \*", ("kOuterTap",), None),
]


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    contract = {m.group(1): float(m.group(2))
                for m in CONSTANT.finditer(pathlib.Path(sys.argv[1]).read_text())}
    problems, checked = [], 0

    def expect(where, what, value, name):
        nonlocal checked
        checked += 1
        if name not in contract:
            problems.append(f"{where}: {what}: contract.hpp has no {name}")
        elif abs(value - contract[name]) > 1e-12 * max(1.0, abs(contract[name])):
            problems.append(f"{where}: {what} is {value:g}, contract.hpp's {name} is {contract[name]:g}")

    for folder in sys.argv[2:]:
        for shader in sorted(pathlib.Path(folder).glob("*.frag")) + sorted(pathlib.Path(folder).glob("*.vert")):
            for number, line in enumerate(shader.read_text().splitlines(), 1):
                where = f"{shader}:{number}"
                if line.lstrip().startswith("//"):
                    continue
                m = BINDING.search(line)
                if m and m.group(2) == "InvResolution":
                    expect(where, "binding of InvResolution", float(m.group(1)), "kInvResolutionBinding")
                elif m and m.group(2) == "sampler2D" and m.group(3) in SAMPLER_UNIT:
                    expect(where, f"unit of {m.group(3)}", float(m.group(1)), SAMPLER_UNIT[m.group(3)])
                m = LOCATION.search(line)
                if m and (shader.name, m.group(2)) in UNIFORM_LOCATION:
                    expect(where, f"location of {m.group(2)}", float(m.group(1)),
                           UNIFORM_LOCATION[(shader.name, m.group(2))])
                for pattern, names, needs in LITERALS:
                    if needs and needs not in line:
                        continue
                    m = re.search(pattern, line)
                    if m:
                        for group, name in enumerate(names, 1):
                            expect(where, f"literal {m.group(group)}", float(m.group(group)), name)
    for problem in problems:
        print(problem)
    print(f"{checked} values checked against contract.hpp: " + ("all agree" if not problems
                                                                else f"{len(problems)} disagree"))
    return 1 if problems or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
