import sys,re,collections
for f in sys.argv[1:]:
    tries=[]; cur=None
    for line in open(f):
        m=re.search(r"t ([\d.]+) it (\d+) chg (\S+)",line)
        if not m: continue
        t,it,chg=float(m.group(1)),int(m.group(2)),float(m.group(3))
        if it==1:
            cur=[t,[]]; tries.append(cur)
        cur[1].append(chg)
    h=collections.Counter(len(x[1]) for x in tries)
    # by time window
    w=collections.defaultdict(list)
    for t,c in tries: w[int(t*10)].append(len(c))
    print(f, "tries",len(tries),"passes",sum(len(x[1]) for x in tries), "hist",sorted(h.items()))
    print("  per 0.1 s window mean passes:", " ".join("%d:%.1f"%(k,sum(v)/len(v)) for k,v in sorted(w.items())))
