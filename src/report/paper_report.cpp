#include "report/report.hpp"
namespace rollspin::report {
ReportOutcome paperReport(const ReportOptions&) { return {}; }
}
