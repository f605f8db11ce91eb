# opt NAME: the `crawlsim run` option of robustness run NAME (issue 33), sourced by robust.sh
# and trial.sh
opt() {
  case $1 in
    nominal) echo "" ;; ramp0.1) echo "--ramp 0.1" ;; ramp0.5) echo "--ramp 0.5" ;;
    mu0.6) echo "--friction 0.6" ;; mu1.0) echo "--friction 1.0" ;;
    m25g) echo "--support-mass 0.025" ;; m75g) echo "--support-mass 0.075" ;;
    tau0.5x) echo "--tau 0.01" ;; tau2x) echo "--tau 0.04" ;;
    dt_half) echo "--dt 0.0005" ;;
  esac
}
