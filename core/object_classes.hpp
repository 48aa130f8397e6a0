#pragma once
// The object classes littermap knows: the litter classes (TACO-aligned) and the natural
// look-alikes a detector must not call litter. The simulator places them, the classifier learns
// them, the evaluation tabulates them, in this order.

#include <string>
#include <string_view>
#include <vector>

namespace littermap {

const std::vector<std::string>& LitterClasses();
const std::vector<std::string>& NaturalClasses();

bool IsLitterClass(std::string_view class_name);
// A natural class, or "natural" itself.
bool IsNaturalClass(std::string_view class_name);

}  // namespace littermap
