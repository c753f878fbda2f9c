#!/usr/bin/env python3
"""Writes the seed corpora (corpus/<m>/seed-*) and the hand-made regression inputs
(regressions/<m>/*) of the fuzzing harnesses, encoding values the way fuzz_input.h decodes
them. Run it after changing the decoder: python3 tools/fuzz/make_inputs.py"""
import os
import random
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
SPECIAL = {"0": 0, "1": 2, "nan": 5, "inf": 7, "-inf": 8, "1e300": 9, "max": 11, "denorm_min": 13,
           "2^24": 18, "1e262": 23, "1e308": 25, "2e-162": 28}


class Enc:
    def __init__(self):
        self.b = bytearray()

    def byte(self, v):
        self.b.append(v & 255)
        return self

    def flag(self, on):
        return self.byte(1 if on else 0)

    def range(self, lo, hi, value):
        self.b += struct.pack(">H", value - lo)
        return self

    def special(self, name):
        return self.byte(SPECIAL[name])

    def pixel(self, x):  # real(): an ordinary value on the 1/16 grid
        self.byte(100)
        return self.range(-1024, 3072, int(round(x * 16)))

    def raw(self, x):  # real(): any bit pattern
        self.byte(240)
        self.b += struct.pack(">d", x)
        return self

    def color(self, r, g, b):
        return self.byte(r).byte(g).byte(b)


def write(path, data):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(bytes(data))


def fill_checker(w0, uv0=None):
    """m4: fill_triangle called directly in kChecker mode, perspective-correct, vertex 0 with
    clip-space w = w0 (a value name or a float) and, if given, uv0."""
    e = Enc().byte(4)  # case 4: fill
    e.range(1, 48, 48).range(1, 48, 48).color(0, 0, 0)  # a 48x48 image
    e.byte(5 << 5)  # needs: kChecker, no depth test, perspective-correct
    e.color(0, 0, 0)  # background
    e.flag(True).range(0, 3, 0)  # default ambient, no lights
    e.color(200, 100, 50).color(10, 20, 30)  # material, flat color
    for i, (x, y) in enumerate([(2, 2), (40, 2), (2, 40)]):
        e.pixel(x).pixel(y).flag(True).byte(100).range(-4096, 4096, 0)  # z = 0
        if i == 0:
            e.flag(False)
            e.special(w0) if isinstance(w0, str) else e.raw(w0)
        else:
            e.flag(True)  # w = 1
        e.flag(True).flag(True).flag(True)  # color, normal, world: defaults
        if i == 0 and uv0 is not None:
            e.flag(False)
            for c in uv0:
                e.special(c) if isinstance(c, str) else e.raw(c)
        else:
            e.flag(True)
    return e.b


def main():
    rng = random.Random(19)
    for m, cases in (("m1", 5), ("m2", 5), ("m3", 8), ("m4", 6)):
        for i in range(12):
            data = bytearray([i % cases]) + bytearray(rng.randrange(256) for _ in range(rng.randrange(24, 160)))
            write(os.path.join(HERE, "corpus", m, "seed-%02d" % i), data)
    # Milestone 5 (its own generator, so the seeds above stay as they were): 24 seeds over its
    # five cases, longer ones for the scenes (textures, meshes, lights and shadow settings).
    rng5 = random.Random(20)
    for i in range(24):
        data = bytearray([i % 5]) + bytearray(rng5.randrange(256) for _ in range(rng5.randrange(48, 400)))
        write(os.path.join(HERE, "corpus", "m5", "seed-%02d" % i), data)
    # Issue 19: fill_triangle's inline perspective weights had no fallback, so these made the
    # uv NaN and m4::checker converted floor(NaN * 8) to long long (undefined behaviour).
    reg = os.path.join(HERE, "regressions", "m4")
    write(os.path.join(reg, "fill-w-denorm-min"), fill_checker("denorm_min"))
    write(os.path.join(reg, "fill-w-zero"), fill_checker("0"))
    write(os.path.join(reg, "fill-w-nan"), fill_checker("nan"))
    write(os.path.join(reg, "fill-uv-nan"), fill_checker("1", ["nan", "1"]))
    write(os.path.join(reg, "fill-uv-inf"), fill_checker("1", ["inf", "-inf"]))
    write(os.path.join(reg, "fill-uv-1e300"), fill_checker("1", ["1e300", 1e300]))


if __name__ == "__main__":
    main()
