#include "capture/ros_codec.hpp"
