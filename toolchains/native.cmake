# Native build on the development machine or the vehicle's compute module (Debian 12, g++ 12).
set(CMAKE_C_COMPILER gcc)
set(CMAKE_CXX_COMPILER g++)
