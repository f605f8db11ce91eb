import re,sys
lines=open(sys.argv[1]).read().split('\n')
lo,hi,minp=float(sys.argv[2]),float(sys.argv[3]),int(sys.argv[4])
tries=[];cur=None
for ln in lines:
    m=re.search(r"t ([\d.]+) it (\d+) chg (\S+)",ln)
    if not m:
        if 'RELEASE' in ln and cur: cur[1].append(ln)
        continue
    if int(m.group(2))==1:
        cur=[float(m.group(1)),[]]; tries.append(cur)
    cur[1].append(ln)
n=0
for t in tries:
    if len(t[1])>=minp and lo<t[0]<hi:
        print("=== t",t[0],len(t[1]))
        for l in t[1]:
            l=re.sub(r" L[A-H] \S+","",l)
            print(l[:330])
        n+=1
        if n>=int(sys.argv[5]): break
