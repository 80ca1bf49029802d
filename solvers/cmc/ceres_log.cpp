// Ceres's glog level (ceres_log.h).
#include "bezierpde/solvers/cmc/ceres_log.h"

#include <glog/logging.h>

namespace bpde {

void quiet_ceres_log() { FLAGS_minloglevel = google::GLOG_FATAL; }

}  // namespace bpde
