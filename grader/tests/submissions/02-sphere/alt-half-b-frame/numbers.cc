#include "numbers.hh"

#include <charconv>
#include <string_view>
#include <system_error>

namespace vl::stage02 {

void write_number(std::ostream& s, double x) {
    char text[64];
    const auto [end, error] = std::to_chars(text, text + sizeof text, x);
    if (error == std::errc()) s << std::string_view(text, static_cast<std::size_t>(end - text));
}

}  // namespace vl::stage02
