"""Checks run_segment_tf_test.cmake's three renders (PIL from the venv reads the PNGs).

none.png: no segment has its own table and the volume's is transparent: all black.
red.png: label 1 red and opaque at every HU: each pixel pure red or black, the red ones the
sphere's disc (radius 12 voxels of the phantom's 64, about 7.5 pixels in this 96 x 72 frame:
about 175 pixels; 100 ... 1000 allows for the camera's framing), the frame's middle among them.
bone.png: label 1 with the CT-Bone preset: something shows (not all black).
"""
import sys

try:
    from PIL import Image
except ImportError:
    sys.exit("Pillow is missing from the venv: run scripts/bootstrap")


def pixels(path):
    img = Image.open(path).convert("RGB")
    return img, [img.getpixel((x, y)) for y in range(img.height) for x in range(img.width)]


_, none = pixels(sys.argv[1])
red_img, red = pixels(sys.argv[2])
_, bone = pixels(sys.argv[3])
assert all(p == (0, 0, 0) for p in none), "none.png: a pixel is not the background"
n_red = sum(p == (255, 0, 0) for p in red)
n_black = sum(p == (0, 0, 0) for p in red)
assert n_red + n_black == len(red), f"red.png: {len(red) - n_red - n_black} pixels neither red nor black"
middle = red_img.getpixel((red_img.width // 2, red_img.height // 2))
assert middle == (255, 0, 0), f"red.png: the middle pixel is {middle}, not red"
assert 100 < n_red < 1000, f"red.png: {n_red} red pixels"
n_bone = sum(p != (0, 0, 0) for p in bone)
assert n_bone > 100, f"bone.png: only {n_bone} pixels show"
print(f"segment-tf: {n_red} red pixels of {len(red)}; CT-Bone shows {n_bone}")
