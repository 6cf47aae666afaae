__kernel void placeholder() {}
