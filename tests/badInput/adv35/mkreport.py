import os, re, glob, html
here = os.path.dirname(os.path.abspath(__file__))
exec(open(os.path.join(here, "verdicts.py")).read())
cls = {"r": "1 restart/changed input", "o": "2 re-run/-overwrite", "c": "3 concurrent", "i": "4 input (ind)",
       "b": "4 input (blast)", "t": "4 input (tools)", "v": "4/1/3 verification", "k": "5 corrupted output", "s": "6 resources"}
rows = []; counts = {}
for f in sorted(glob.glob(os.path.join(here, "cases", "*.sh"))):
    cid = os.path.basename(f)[:-3]
    lines = open(f).read().splitlines()
    desc = lines[1][2:].split(": ", 1)[1] if ": " in lines[1] else lines[1]
    cmd = " ; ".join(l.strip() for l in lines[3:])
    out = os.path.join(here, "out", cid + ".txt")
    o = open(out, errors="replace").read().splitlines() if os.path.exists(out) else ["(not run)"]
    keep = [l.strip() for l in o if l.strip() and not l.startswith("    From function") and not l.startswith("    in file")
            and l.strip() not in ("FOAM exiting", "End") and not l.startswith("[case exit")
            and "usage:" not in l and not l.strip().startswith("[-")]
    # the message lines and the exit code(s)
    msg = [l for l in keep if not re.match(r"^(rc|rc1|rc2|first rc|second rc|run rc|killed rc|solidToFoam rc|cellMesh rc|plot rc|restart rc|overwrite rc|clean rc)=", l)][:4]
    rcs = [l for l in keep if re.match(r"^[a-zA-Z ]*rc[12]?=", l)]
    obs = " / ".join(x[:260] for x in msg) + ("  [" + "; ".join(rcs) + "]" if rcs else "")
    c, v, note = V.get(cid, (cls[cid[0]], "OK", ""))
    if cid[0] in cls and cid in V: c = cls[cid[0]] if not V[cid][0] else V[cid][0]
    counts[v] = counts.get(v, 0) + 1
    esc = lambda s: s.replace("|", "\\|").replace("\n", " ")
    rows.append("| %s | %s | %s | %s | %s | **%s**%s |" % (cid, esc(c), esc(desc), "`" + esc(cmd[:220]).replace("`", "'") + "`", esc(obs), v, (": " + esc(note)) if note else ""))
print("COUNTS", counts)
open(os.path.join(here, "table.md"), "w").write(
    "| id | class | case | command (after `. lib.sh`) | observed (message lines, [exit codes]) | verdict |\n|---|---|---|---|---|---|\n" + "\n".join(rows) + "\n")
