#pragma once
#include "drivers/cdr/cdr_reader.h"
#include "drivers/cdr/cdr_writer.h"
#include "drivers/recording/topics.h"
#include "nav/types/time.h"

namespace deepnav {

// The std_msgs/Header that starts the messages of deepnav's topics: the stamp, t_us on the system clock
// as builtin_interfaces/Time (floor division keeps nanosec >= 0), then the topic's frame_id.
void writeStampedHeader(cdr::CdrWriter& w, TimeUs t_us, Topic topic);

// Reads one back into *t_us: false when it is cut short or its nanosec is not below one second.
bool readStampedHeader(cdr::CdrReader& r, TimeUs* t_us);

}  // namespace deepnav
