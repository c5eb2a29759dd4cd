// Routes messages to the engine's logger callback (per simulation; no global logger).
#pragma once
#include <string>

#include "pf/pf.h"

namespace pf {

class Log {
public:
    Log() = default;
    explicit Log(pf_logger logger) : logger_(logger) {}
    // Logs `message` at `level` and returns `code`, so error paths read `return log.error(...)`.
    pf_result emit(pf_log_level level, pf_result code, const std::string& message) const {
        if (logger_.fn) logger_.fn(logger_.user, level, code, message.c_str());
        return code;
    }
    pf_result error(pf_result code, const std::string& message) const {
        return emit(PF_LOG_ERROR, code, message);
    }
    void warning(const std::string& message) const { emit(PF_LOG_WARNING, PF_OK, message); }
    void info(const std::string& message) const { emit(PF_LOG_INFO, PF_OK, message); }

private:
    pf_logger logger_{};
};

}  // namespace pf
