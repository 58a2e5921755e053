module top(clock,host_write,host_address,host_data,start,done,pixel_r,pixel_g,pixel_b,pixel_a,has_sample,ext_addr$0,ext_addr$1,ext_addr$2,ext_addr$3,ext_data$0,ext_data$1,ext_data$2,ext_data$3,load_enable,load_module,load_address,load_data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  start;
    output reg  done;
    output reg  [31:0] pixel_r;
    output reg  [15:0] pixel_g;
    output reg  [15:0] pixel_b;
    output reg  [15:0] pixel_a;
    output reg  has_sample;
    output reg  [31:0] ext_addr$0;
    output reg  [31:0] ext_addr$1;
    output reg  [31:0] ext_addr$2;
    output reg  [31:0] ext_addr$3;
    input wire  [15:0] ext_data$0;
    input wire  [15:0] ext_data$1;
    input wire  [15:0] ext_data$2;
    input wire  [15:0] ext_data$3;
    input wire  load_enable;
    input wire  [7:0] load_module;
    input wire  [31:0] load_address;
    input wire  [15:0] load_data;
    
    // Stub signals
    reg  fetch$clock;
    reg  fetch$host_write;
    reg  [23:0] fetch$host_address;
    reg  [63:0] fetch$host_data;
    reg  fetch$start;
    wire  fetch$valid;
    wire  [15:0] fetch$cur$0;
    wire  [15:0] fetch$cur$1;
    wire  [15:0] fetch$cur$2;
    wire  [15:0] fetch$cur$3;
    wire  [15:0] fetch$next$0;
    wire  [15:0] fetch$next$1;
    wire  [15:0] fetch$next$2;
    wire  [15:0] fetch$next$3;
    wire  [31:0] fetch$ext_addr$0;
    wire  [31:0] fetch$ext_addr$1;
    wire  [31:0] fetch$ext_addr$2;
    wire  [31:0] fetch$ext_addr$3;
    reg  [15:0] fetch$ext_data$0;
    reg  [15:0] fetch$ext_data$1;
    reg  [15:0] fetch$ext_data$2;
    reg  [15:0] fetch$ext_data$3;
    reg  fetch$load_enable;
    reg  [7:0] fetch$load_module;
    reg  [31:0] fetch$load_address;
    reg  [15:0] fetch$load_data;
    reg  pipeline$clock;
    reg  pipeline$host_write;
    reg  [23:0] pipeline$host_address;
    reg  [63:0] pipeline$host_data;
    reg  pipeline$start;
    reg  pipeline$valid;
    reg  [15:0] pipeline$cur$0;
    reg  [15:0] pipeline$cur$1;
    reg  [15:0] pipeline$cur$2;
    reg  [15:0] pipeline$cur$3;
    reg  [15:0] pipeline$next$0;
    reg  [15:0] pipeline$next$1;
    reg  [15:0] pipeline$next$2;
    reg  [15:0] pipeline$next$3;
    wire  pipeline$done;
    wire  [31:0] pipeline$pixel_r;
    wire  [15:0] pipeline$pixel_g;
    wire  [15:0] pipeline$pixel_b;
    wire  [15:0] pipeline$pixel_a;
    wire  pipeline$has_sample;
    
    // Sub module instances
    top$fetch fetch(
        .clock(fetch$clock),
        .host_write(fetch$host_write),
        .host_address(fetch$host_address),
        .host_data(fetch$host_data),
        .start(fetch$start),
        .valid(fetch$valid),
        .cur$0(fetch$cur$0),
        .cur$1(fetch$cur$1),
        .cur$2(fetch$cur$2),
        .cur$3(fetch$cur$3),
        .next$0(fetch$next$0),
        .next$1(fetch$next$1),
        .next$2(fetch$next$2),
        .next$3(fetch$next$3),
        .ext_addr$0(fetch$ext_addr$0),
        .ext_addr$1(fetch$ext_addr$1),
        .ext_addr$2(fetch$ext_addr$2),
        .ext_addr$3(fetch$ext_addr$3),
        .ext_data$0(fetch$ext_data$0),
        .ext_data$1(fetch$ext_data$1),
        .ext_data$2(fetch$ext_data$2),
        .ext_data$3(fetch$ext_data$3),
        .load_enable(fetch$load_enable),
        .load_module(fetch$load_module),
        .load_address(fetch$load_address),
        .load_data(fetch$load_data)
    );
    top$pipeline pipeline(
        .clock(pipeline$clock),
        .host_write(pipeline$host_write),
        .host_address(pipeline$host_address),
        .host_data(pipeline$host_data),
        .start(pipeline$start),
        .valid(pipeline$valid),
        .cur$0(pipeline$cur$0),
        .cur$1(pipeline$cur$1),
        .cur$2(pipeline$cur$2),
        .cur$3(pipeline$cur$3),
        .next$0(pipeline$next$0),
        .next$1(pipeline$next$1),
        .next$2(pipeline$next$2),
        .next$3(pipeline$next$3),
        .done(pipeline$done),
        .pixel_r(pipeline$pixel_r),
        .pixel_g(pipeline$pixel_g),
        .pixel_b(pipeline$pixel_b),
        .pixel_a(pipeline$pixel_a),
        .has_sample(pipeline$has_sample)
    );
    
    // Update code
    always @(*) begin
        fetch$clock = clock;
        pipeline$clock = clock;
        fetch$start = start;
        fetch$host_write = host_write;
        fetch$host_address = host_address;
        fetch$host_data = host_data;
        fetch$load_enable = load_enable;
        fetch$load_module = load_module;
        fetch$load_address = load_address;
        fetch$load_data = load_data;
        pipeline$start = start;
        pipeline$host_write = host_write;
        pipeline$host_address = host_address;
        pipeline$host_data = host_data;
        pipeline$valid = fetch$valid;
        pipeline$cur$0 = fetch$cur$0;
        pipeline$next$0 = fetch$next$0;
        ext_addr$0 = fetch$ext_addr$0;
        fetch$ext_data$0 = ext_data$0;
        pipeline$cur$1 = fetch$cur$1;
        pipeline$next$1 = fetch$next$1;
        ext_addr$1 = fetch$ext_addr$1;
        fetch$ext_data$1 = ext_data$1;
        pipeline$cur$2 = fetch$cur$2;
        pipeline$next$2 = fetch$next$2;
        ext_addr$2 = fetch$ext_addr$2;
        fetch$ext_data$2 = ext_data$2;
        pipeline$cur$3 = fetch$cur$3;
        pipeline$next$3 = fetch$next$3;
        ext_addr$3 = fetch$ext_addr$3;
        fetch$ext_data$3 = ext_data$3;
        done = pipeline$done;
        pixel_r = pipeline$pixel_r;
        pixel_g = pipeline$pixel_g;
        pixel_b = pipeline$pixel_b;
        pixel_a = pipeline$pixel_a;
        has_sample = pipeline$has_sample;
    end
    
endmodule // top
