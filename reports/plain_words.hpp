#pragma once
// Figures put into words for park staff: counts with the right noun form, positions as
// directions from the dock, kinds of litter in lower case mid-sentence.

#include <cstddef>
#include <string>
#include <string_view>

namespace littermap::reports {

// "1 bottle", "3 bottles", "1 204 items" (a thin space).
std::string CountOf(std::size_t n, std::string_view one, std::string_view many);

// "1 cup", "2 food containers": the class's own noun (reports/class_palette.hpp).
std::string ClassCount(std::string_view class_name, std::size_t n);

// "12 m east and 3 m south of the dock", "2 m west of the dock", "at the dock": x east, y north,
// in metres, rounded to `decimals`; a component that rounds to zero is left out.
std::string FromTheDock(double x_m, double y_m, int decimals);

}  // namespace littermap::reports
