"""Render a preset unfiltered and filtered, zoomed out, and plot them side
by side with matplotlib (docs/PYTHON.md).

    PYTHONPATH=build/python python3 examples/render_preset.py camouflage -o camouflage.png
"""
import argparse

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import numpy as np

import stochtex


def srgb(linear):
    """Linear light to sRGB codes in [0, 1] for display (the images are linear)."""
    c = np.clip(linear, 0.0, 1.0)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("preset", nargs="?", default="camouflage", choices=stochtex.presets())
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--scale", type=float, default=6.0, help="example texels per pixel")
    parser.add_argument("-o", "--output", default="render_preset.png")
    args = parser.parse_args()

    pattern = stochtex.pattern(args.preset)
    fig, axes = plt.subplots(1, 3, figsize=(12, 4.4), constrained_layout=True)
    for ax, name in zip(axes, ["none", "paper", "smooth"]):
        image = stochtex.Renderer(pattern, filter=name).render(size=args.size, scale=args.scale)
        ax.imshow(srgb(image), interpolation="nearest")
        ax.set_title(f"{args.preset}, filter {name}, scale {args.scale:g}")
        ax.axis("off")
    fig.savefig(args.output, dpi=100)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
