// libFuzzer target: the condition parser of manifest `hierarchy.<id>.opts` keys.
#include "templates/Condition.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const std::map<std::string, rs::Value> options{
        {"clavicle", true}, {"unchain", false}, {"orient", std::string("auto")}, {"count", 3LL},
        {"length", 0.25}, {"branches", std::string("[L, R]")}, {"empty", std::string()}};
    (void)rs::templates::evaluateCondition(std::string(reinterpret_cast<const char*>(data), size), options);
    return 0;
}
