#pragma once
// Lengths in messages: four significant digits and the unit ("0.5 mm", "98.99 mm").
#include <sstream>
#include <string>

namespace popup {

inline std::string millimetres(double value)
{
    std::ostringstream s;
    s.precision(4);
    s << value << " mm";
    return s.str();
}

} // namespace popup
