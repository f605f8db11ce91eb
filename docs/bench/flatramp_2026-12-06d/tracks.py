import h5py, numpy as np, sys, glob, os
for fn in sorted(glob.glob(sys.argv[1]+'/*.h5')):
    try:
        f=h5py.File(fn,'r'); r=f['run']; t=r['time'][:]; x=r['support/position'][:]; q=r['support/orientation'][:]
    except Exception as e:
        print(fn, 'unreadable', e); continue
    xs=[np.interp(k,t,x[:,0]) if t[-1]>=k-1e-9 else float('nan') for k in range(10)]
    cosang = np.clip(1 - 2 * (q[:, 1] ** 2 + q[:, 3] ** 2), -1, 1)
    errs=[(xs[k]-39*(k-1))/(39*(k-1))*100 for k in range(2,10)]
    w=max(range(8),key=lambda i:abs(errs[i]))
    print(f"{os.path.basename(fn):28s} x2..9 {' '.join(f'{v:.1f}' for v in xs[2:])} worst {errs[w]:+.1f}% ({w+2} s) x9 {(xs[9]-312)/312*100:+.1f}% z {abs(x[:,2]).max():.2f} tilt {np.degrees(np.arccos(cosang)).max():.2f} ramp {r.attrs.get('ramp_s')}")
