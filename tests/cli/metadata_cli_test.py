"""Outputs that remember their scene (issue 53), through the CLI as a user
meets it: every format round-trips through `--from`; stills and figures
re-render byte for byte (figures with SOURCE_DATE_EPOCH), clips decode to
the same frames; what --no-metadata leaves out; the bad-input cases; and the
timeline's files (CSV + sidecar, JSON, .npy, .npz) read by the tools people
use, with no options. The metadata is read back here by independent readers
(a PNG chunk walk with zlib's CRC, JPEG segments, ffprobe, pdfinfo, an XML
parser), never by rollspin's own reader alone.

Run by ctest (MetadataCli.*) with ROLLSPIN_BINARY set; label gl (renders).
"""
import csv
import json
import os
import struct
import subprocess
import xml.etree.ElementTree as ElementTree
import zlib
from pathlib import Path

import numpy as np
import pandas
import pytest

CLI = os.environ["ROLLSPIN_BINARY"]
SMALL = ["--width", "96", "--height", "64"]
# A clip of 3 frames at 96x64, low quality: the cheapest clip that is still a clip.
CLIP = ["--quality", "low", *SMALL, "--frames", "2:4"]


def run(*args, env=None, cwd=None):
    full_env = dict(os.environ, **(env or {}))
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, env=full_env, cwd=cwd)


def ok(*args, **kwargs):
    done = run(*args, **kwargs)
    assert done.returncode == 0, done.stderr
    return done


def png_text_chunks(path):
    """iTXt chunks of a PNG, each chunk's CRC checked with zlib."""
    data = Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, chunks = 8, {}
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        assert struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])[0] == zlib.crc32(kind + body)
        if kind == b"iTXt":
            key, rest = body.split(b"\0", 1)
            chunks[key.decode()] = rest[2:].split(b"\0", 2)[2].decode()
        pos += 12 + length
    return chunks


def jpeg_comments(path):
    data = Path(path).read_bytes()
    pos, comments = 2, []
    while data[pos] == 0xFF and data[pos + 1] != 0xDA:
        length = struct.unpack(">H", data[pos + 2:pos + 4])[0]
        if data[pos + 1] == 0xFE:
            comments.append(data[pos + 4:pos + 2 + length])
        pos += 2 + length
    return comments


def stored_scene(path):
    return ok("scene", "--from", path).stdout


def test_png_still_remembers_and_rerenders_byte_for_byte(tmp_path):
    first = tmp_path / "torus.png"
    ok("render", "torus", "--still", "--at", "fraction=0.25", *SMALL, "-o", first)
    chunks = png_text_chunks(first)
    assert set(chunks) >= {"rollspin:scene", "rollspin:job", "Description", "Software"}
    assert chunks["Description"].startswith("A ball of radius ") and "torus" in chunks["Description"]
    assert chunks["Software"].startswith("rollspin ")
    assert "at: fraction=0.25" in chunks["rollspin:job"] and "render: still" in chunks["rollspin:job"]
    assert stored_scene(first) == chunks["rollspin:scene"]
    assert "width = 96" in chunks["rollspin:scene"]  # the size flags became keys
    again = tmp_path / "again.png"
    ok("render", "--from", first, "-o", again)
    assert again.read_bytes() == first.read_bytes()
    # The default output: the job's scene name, the same format.
    ok("render", "--from", first, cwd=tmp_path)
    assert (tmp_path / "output" / "torus.png").read_bytes() == first.read_bytes()


def test_jpeg_still_remembers_and_rerenders_byte_for_byte(tmp_path):
    first = tmp_path / "a.jpg"
    ok("render", "lollipop", "--still", *SMALL, "-o", first)
    comments = jpeg_comments(first)
    assert any(c.startswith(b"rollspin:scene\0") for c in comments)
    assert any(c.startswith(b"Description\0A ball of radius") for c in comments)
    again = tmp_path / "b.jpg"
    ok("render", "--from", first, "-o", again)
    assert again.read_bytes() == first.read_bytes()
    assert stored_scene(again) == stored_scene(first)


FIGURE = ["--set", "figure.width_mm=40", "--set", "render.dpi=72"]


def test_pdf_figure_is_reproducible_with_source_date_epoch(tmp_path):
    env = {"SOURCE_DATE_EPOCH": "1700000000"}
    first = tmp_path / "fig.pdf"
    ok("render", "lollipop", "--still", *FIGURE, "-o", first, env=env)
    info = subprocess.run(["pdfinfo", first], capture_output=True, text=True).stdout
    description = next(line for line in info.splitlines() if line.startswith("Subject:"))
    assert "A ball of radius" in description
    assert "Creator:" in info and "rollspin" in info
    assert "2023" in next(line for line in info.splitlines() if line.startswith("CreationDate:"))
    assert b"<rollspin:scene>" in first.read_bytes()  # the XMP packet
    again = tmp_path / "again.pdf"
    ok("render", "--from", first, "-o", again, env=env)
    assert again.read_bytes() == first.read_bytes()
    data = first.read_bytes()
    job_at = data.rindex(b"/RollspinJob <") + len(b"/RollspinJob <")
    assert b"render: figure" in bytes.fromhex(data[job_at:data.index(b">", job_at)].decode())
    assert "kind = \"circle\"" in stored_scene(first)


def test_svg_figure_has_title_desc_metadata_and_rerenders(tmp_path):
    env = {"SOURCE_DATE_EPOCH": "1700000000"}
    first = tmp_path / "fig.svg"
    ok("render", "lollipop", "--still", *FIGURE, "--set", "render.title=\"Lollipop & <friends>\"", "-o", first, env=env)
    root = ElementTree.parse(first).getroot()
    ns = {"svg": "http://www.w3.org/2000/svg", "r": "urn:rollspin:metadata"}
    assert root.find("svg:title", ns).text == "Lollipop & <friends>"
    assert root.find("svg:desc", ns).text.startswith("A ball of radius")
    scene = root.find("svg:metadata/r:metadata/r:scene", ns).text
    assert scene == stored_scene(first)
    again = tmp_path / "again.svg"
    ok("render", "--from", first, "-o", again, env=env)
    assert again.read_bytes() == first.read_bytes()


def decoded_frames(path):
    done = subprocess.run(["ffmpeg", "-v", "error", "-i", path, "-f", "rawvideo", "-pix_fmt", "rgba", "-"],
                          capture_output=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def ffprobe_tags(path):
    done = subprocess.run(["ffprobe", "-v", "error", "-show_entries", "format_tags", "-of", "json", path],
                          capture_output=True, text=True)
    return {k.lower(): v for k, v in json.loads(done.stdout)["format"]["tags"].items()}


@pytest.mark.parametrize("extension", [".mp4", ".webm", ".mov", ".gif"])
def test_clip_remembers_and_decodes_to_the_same_frames(tmp_path, extension):
    first = tmp_path / f"clip{extension}"
    ok("render", "lollipop", *CLIP, "-o", first, "--quiet")
    if extension == ".gif":
        data = first.read_bytes()
        assert b"\x21\xfe" in data and b"rollspin:scene\0" in data
    else:
        tags = ffprobe_tags(first)
        assert "rollspin_scene" in tags and tags["description"].startswith("A ball of radius")
        assert "frames: 2:4" in tags["rollspin_job"]
    again = tmp_path / f"again{extension}"
    ok("render", "--from", first, "-o", again, "--quiet")
    frames = decoded_frames(first)
    assert len(frames) == 3 * 96 * 64 * 4 and decoded_frames(again) == frames
    assert stored_scene(again) == stored_scene(first)


def test_joined_shards_remember_the_whole_clip(tmp_path):
    shards = ["render", "lollipop", "--quality", "low", *SMALL, "--set", "animation.duration=0.4", "--quiet",
              "-o", tmp_path / "c.mp4"]
    ok(*shards, "--shard", "1/2")
    ok(*shards, "--shard", "2/2")
    ok("join", tmp_path / "c.part-1-of-2.mp4", tmp_path / "c.part-2-of-2.mp4", "-o", tmp_path / "c.mp4")
    assert "frames: 0:" in ffprobe_tags(tmp_path / "c.part-1-of-2.mp4")["rollspin_job"]  # the first part's frames
    tags = ffprobe_tags(tmp_path / "c.mp4")
    assert "frames:" not in tags["rollspin_job"] and "render: clip" in tags["rollspin_job"]
    assert stored_scene(tmp_path / "c.mp4") == stored_scene(tmp_path / "c.part-2-of-2.mp4")
    ok("render", "--from", tmp_path / "c.mp4", "-o", tmp_path / "again.mp4", "--quiet")
    # The whole clip again, encoded in one piece (the parts were encoded apart: the same
    # frames rendered, not the same bytes decoded).
    assert len(decoded_frames(tmp_path / "again.mp4")) == len(decoded_frames(tmp_path / "c.mp4"))


def test_no_metadata_leaves_it_all_out(tmp_path):
    png, mp4 = tmp_path / "bare.png", tmp_path / "bare.mp4"
    ok("render", "lollipop", "--still", *SMALL, "--no-metadata", "-o", png)
    ok("render", "lollipop", *CLIP, "--no-metadata", "-o", mp4, "--quiet")
    assert png_text_chunks(png) == {}
    # join's own tags stay (a hash of the scene, not the scene); the scene and the description go.
    assert not {"rollspin_scene", "rollspin_job", "description"} & set(ffprobe_tags(mp4))
    for path in (png, mp4):
        done = run("scene", "--from", path)
        assert done.returncode == 2 and str(path) in done.stderr and "no rollspin metadata" in done.stderr, done.stderr


def png_with_chunks(bare, chunks):
    data = bare.read_bytes()
    extra = b""
    for key, value in chunks.items():
        body = b"iTXt" + key.encode() + b"\0\0\0\0\0" + value.encode()
        extra += struct.pack(">I", len(body) - 4) + body + struct.pack(">I", zlib.crc32(body))
    return data[:-12] + extra + data[-12:]


def test_bad_metadata_is_exit_2_naming_the_file_and_what_is_missing(tmp_path):
    good = tmp_path / "good.png"
    ok("render", "lollipop", "--still", *SMALL, "-o", good)
    data = good.read_bytes()
    truncated = tmp_path / "truncated.png"
    truncated.write_bytes(data[: len(data) // 2])
    done = run("scene", "--from", truncated)
    assert done.returncode == 2 and "truncated.png" in done.stderr and "truncated" in done.stderr, done.stderr
    # A chunk that lost its key: incomplete, not "not rollspin's".
    bare = tmp_path / "bare.png"
    ok("render", "lollipop", "--still", *SMALL, "--no-metadata", "-o", bare)
    partial = tmp_path / "partial.png"
    partial.write_bytes(png_with_chunks(bare, {"rollspin:scene": "[ball]\nradius = 1\n"}))
    done = run("render", "--from", partial)
    assert done.returncode == 2 and "partial.png" in done.stderr and "rollspin:job" in done.stderr, done.stderr
    # A scene that does not load: the loader's message, at the output's name.
    broken = tmp_path / "broken.png"
    broken.write_bytes(png_with_chunks(bare, {"rollspin:scene": "[ball]\nradius = -1\n", "rollspin:job": "render: still\n",
                                              "Description": "", "Software": "rollspin"}))
    done = run("scene", "--from", broken)
    assert done.returncode == 2 and f"{broken}[rollspin:scene]:2:" in done.stderr, done.stderr
    assert "ball.radius" in done.stderr
    corrupt = bytearray(data)
    corrupt[data.index(b"rollspin:scene") + 40] ^= 0x20  # inside the chunk: its CRC no longer matches
    (tmp_path / "corrupt.png").write_bytes(bytes(corrupt))
    done = run("scene", "--from", tmp_path / "corrupt.png")
    assert done.returncode == 2 and "CRC" in done.stderr, done.stderr
    done = run("scene", "--from", tmp_path / "missing.png")
    assert done.returncode == 2 and "missing.png" in done.stderr


SCENE = '[ball]\nradius = 0.5\n\n[path]\nkind = "circle"\nradius = 2\n'


def test_gltf_glb_and_viewer_html_of_their_shape(tmp_path):
    """The shapes the gltf and viewer branches write, made by hand."""
    gltf = {"asset": {"version": "2.0"}, "nodes": [{"name": "surface"},
                                                  {"name": "ball", "extras": {"rollspin": {"scene": SCENE}}}]}
    (tmp_path / "a.gltf").write_text(json.dumps(gltf))
    text = json.dumps(gltf).encode()
    text += b" " * (-len(text) % 4)
    glb = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text)) + struct.pack("<I4s", len(text), b"JSON") + text
    (tmp_path / "a.glb").write_bytes(glb)
    (tmp_path / "a.html").write_text('<!doctype html><meta name="generator" content="rollspin 0.1.0">'
                                     f'<script type="application/toml" id="rollspin-scene">{SCENE}</script>')
    for name in ("a.gltf", "a.glb", "a.html"):
        assert stored_scene(tmp_path / name) == SCENE, name
    (tmp_path / "b.gltf").write_text(json.dumps({"nodes": [{"name": "ball"}]}))
    done = run("scene", "--from", tmp_path / "b.gltf")
    assert done.returncode == 2 and "b.gltf" in done.stderr and "extras.rollspin.scene" in done.stderr


def test_timeline_csv_reads_with_no_options_and_has_a_sidecar(tmp_path):
    out = tmp_path / "t.csv"
    ok("timeline", "storyboard", "--set", "timeline.samples=41", "-o", out)
    with open(out, newline="") as f:
        rows = list(csv.DictReader(f))
    frame = pandas.read_csv(out)
    assert len(rows) == 41 == len(frame) and list(frame.columns) == list(rows[0])
    assert frame.columns[0] == "s" and frame.columns[-1] == "segment" and frame["segment"].dtype.kind == "i"
    assert float(rows[-1]["qw"]) == pytest.approx(frame["qw"].iloc[-1], rel=1e-15, abs=1e-300)
    sidecar = json.loads((tmp_path / "t.csv.json").read_text())
    assert sidecar["columns"] == list(frame.columns) and sidecar["samples"] == 41
    assert sidecar["method"] and sidecar["steps"] > 0 and sidecar["rollspin"].startswith("rollspin ")
    assert stored_scene(out) == sidecar["scene"]
    commented = tmp_path / "c.csv"
    ok("timeline", "storyboard", "--set", "timeline.samples=41", "-o", commented, "--comment-header")
    assert commented.read_text().startswith("# rollspin timeline:")
    assert pandas.read_csv(commented, comment="#").equals(frame)


def test_timeline_json_npy_npz_read_back_equal_to_the_csv(tmp_path):
    args = ["timeline", "storyboard", "--set", "timeline.samples=33"]
    ok(*args, "-o", tmp_path / "t.csv")
    # round_trip: the exact doubles of the %.17g text (pandas' fast parser may be 1 ulp off).
    frame = pandas.read_csv(tmp_path / "t.csv", float_precision="round_trip")
    ok(*args, "-o", tmp_path / "t.json")
    doc = json.loads((tmp_path / "t.json").read_text())
    assert doc["columns"] == list(frame.columns)
    assert pandas.DataFrame(doc["rows"], columns=doc["columns"]).equals(frame)
    ok(*args, "-o", tmp_path / "t.npy")
    records = np.load(tmp_path / "t.npy")
    assert records.dtype.names == tuple(frame.columns) and records.shape == (33,)
    ok(*args, "-o", tmp_path / "t.npz")
    with np.load(tmp_path / "t.npz") as arrays:
        assert list(arrays.keys()) == list(frame.columns)
        for column in frame.columns:
            assert (records[column] == frame[column].to_numpy()).all(), column
            assert (arrays[column] == frame[column].to_numpy()).all(), column
    assert stored_scene(tmp_path / "t.npz") == doc["scene"]


def test_timeline_refuses_another_extension(tmp_path):
    done = run("timeline", "lollipop", "-o", tmp_path / "t.txt")
    assert done.returncode == 2 and "-o" in done.stderr and ".txt" in done.stderr, done.stderr
    assert not (tmp_path / "t.txt").exists()
