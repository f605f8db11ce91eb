export CRAWLSIM_DATA_DIR=/work/wt-margin17 BIN=/tmp/margin16/crawlsim_old D=/tmp/margin17/g G=/tmp/margin17/g R=/tmp/margin17/runs J=/tmp/margin17/jobs
