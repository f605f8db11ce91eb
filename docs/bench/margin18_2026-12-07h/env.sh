# source me: margin16's scripts (../margin16_2026-12-07g/) with this branch's binary (copied, so a
# rebuild does not change a run in flight) and margin18's folders
export CRAWLSIM_DATA_DIR=/work/wt-margin18 BIN=/tmp/margin18/crawlsim D=/tmp/margin18/g G=/tmp/margin18/g R=/tmp/margin18/runs
