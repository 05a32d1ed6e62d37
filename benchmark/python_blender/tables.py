"""The tables of doc/python_and_blender.md from run.sh's outputs (OUT_DIR:
module.csv, blender.csv, uv_metrics.txt)."""
import csv
import os
import re
import statistics
import sys

out = sys.argv[1]
module = list(csv.DictReader(open(os.path.join(out, "module.csv"))))
print("| mesh | faces | E_d uv_unwrap | E_d unwrap() | E_s uv_unwrap | E_s unwrap() | unwrap (s) | Python overhead (s) | % |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
for r in module:
    print("| %s | %s | %.4f | %.4f | %.4f | %.4f | %.2f | %.4f | %.2f |" % (
        r["mesh"], r["faces"], float(r["cli_E_d"]), float(r["py_E_d"]), float(r["cli_E_s"]), float(r["py_E_s"]),
        float(r["py_unwrap_s"]), float(r["py_overhead_s"]), float(r["py_overhead_pct"])))
same = sum(r["same"] == "True" for r in module)
print("\nidentical E_d and E_s on %d of %d meshes" % (same, len(module)))

metrics = {}
for line in open(os.path.join(out, "uv_metrics.txt")):
    path, *fields = line.split()
    values = dict(f.split("=") for f in fields)
    name = os.path.basename(path)[:-4]
    metrics[name] = values
blender = list(csv.DictReader(open(os.path.join(out, "blender.csv"))))
print("\n| mesh | faces | Smart UV E_s | add-on E_s | Smart UV E_d | add-on E_d | Smart UV charts | add-on charts "
      "| Smart UV crossings / overlap | add-on crossings / overlap | Smart UV (s) | add-on (s) | Blender overhead % |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for r in blender:
    s, a = metrics[r["mesh"] + "_smart_uv"], metrics[r["mesh"] + "_addon"]
    print("| %s | %s | %.2f | %.2f | %.3f | %.3f | %s | %s | %s / %.3f | %s / %.3f | %.2f | %.2f | %.2f |" % (
        r["mesh"], r["faces"], float(s["E_s"]), float(a["E_s"]), float(s["E_d"]), float(a["E_d"]),
        r["smart_charts"], r["addon_charts"], s["crossings"], float(s["overlap"]), a["crossings"],
        float(a["overlap"]), float(r["smart_s"]), float(r["addon_s"]), float(r["overhead_pct"])))
med = lambda key, suffix: statistics.median(float(metrics[r["mesh"] + suffix][key]) for r in blender)
print("\nmedians: E_s Smart UV %.2f, add-on %.2f; E_d Smart UV %.3f, add-on %.3f" % (
    med("E_s", "_smart_uv"), med("E_s", "_addon"), med("E_d", "_smart_uv"), med("E_d", "_addon")))
print("meshes with crossing UV borders: Smart UV %d, add-on %d" % (
    sum(int(metrics[r["mesh"] + "_smart_uv"]["crossings"]) > 0 for r in blender),
    sum(int(metrics[r["mesh"] + "_addon"]["crossings"]) > 0 for r in blender)))
