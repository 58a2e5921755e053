module top$pipeline$control(clock,start,valid,first,unit_valid,unit_first,unit_last,wx$0,wx$1,wx$2,wx$3,wy$0,wy$1,wy$2,wy$3,in_volume,in_inner);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    input wire  valid;
    output reg  first;
    output reg  unit_valid;
    output reg  unit_first;
    output reg  unit_last;
    output reg  [15:0] wx$0;
    output reg  [15:0] wx$1;
    output reg  [15:0] wx$2;
    output reg  [15:0] wx$3;
    output reg  [15:0] wy$0;
    output reg  [15:0] wy$1;
    output reg  [15:0] wy$2;
    output reg  [15:0] wy$3;
    output reg  [7:0] in_volume;
    output reg  [7:0] in_inner;
    
    // Constant declarations
    localparam  last_segment = 16'h7;
    localparam  last_ray = 16'h3b;
    localparam  lane_bit$0 = 8'h1;
    localparam  lane_bit$1 = 8'h2;
    localparam  lane_bit$2 = 8'h4;
    localparam  lane_bit$3 = 8'h8;
    localparam  lane_bit$4 = 8'h10;
    localparam  lane_bit$5 = 8'h20;
    localparam  lane_bit$6 = 8'h40;
    localparam  lane_bit$7 = 8'h80;
    localparam  valid_flag = 64'h1000000000000;
    
    // Stub signals
    reg  [15:0] segment$d;
    wire  [15:0] segment$q;
    reg  segment$clock;
    reg  [15:0] ray$d;
    wire  [15:0] ray$q;
    reg  ray$clock;
    reg  [15:0] scanline$d;
    wire  [15:0] scanline$q;
    reg  scanline$clock;
    reg  late$clock;
    reg  [63:0] late$data_in;
    reg  late$write_enable;
    wire  [63:0] late$data_out;
    reg  [7:0] weights$0$address;
    wire  [31:0] weights$0$data;
    reg  [7:0] weights$1$address;
    wire  [31:0] weights$1$data;
    reg  [7:0] weights$2$address;
    wire  [31:0] weights$2$data;
    reg  [7:0] weights$3$address;
    wire  [31:0] weights$3$data;
    reg  [7:0] bounds$0$address;
    wire  [63:0] bounds$0$data;
    reg  [7:0] bounds$1$address;
    wire  [63:0] bounds$1$data;
    reg  [7:0] bounds$2$address;
    wire  [63:0] bounds$2$data;
    reg  [7:0] bounds$3$address;
    wire  [63:0] bounds$3$data;
    reg  [7:0] inner$0$address;
    wire  [63:0] inner$0$data;
    reg  [7:0] inner$1$address;
    wire  [63:0] inner$1$data;
    reg  [7:0] inner$2$address;
    wire  [63:0] inner$2$data;
    reg  [7:0] inner$3$address;
    wire  [63:0] inner$3$data;
    
    // Local signals
    reg  [15:0] unit_segment;
    reg  [15:0] unit_ray;
    reg  [15:0] unit_scanline;
    reg  [7:0] lane_in$0;
    reg  [7:0] lane_in$1;
    reg  [7:0] lane_in$2;
    reg  [7:0] lane_in$3;
    reg  [7:0] lane_in$4;
    reg  [7:0] lane_in$5;
    reg  [7:0] lane_in$6;
    reg  [7:0] lane_in$7;
    reg  [7:0] lane_inner$0;
    reg  [7:0] lane_inner$1;
    reg  [7:0] lane_inner$2;
    reg  [7:0] lane_inner$3;
    reg  [7:0] lane_inner$4;
    reg  [7:0] lane_inner$5;
    reg  [7:0] lane_inner$6;
    reg  [7:0] lane_inner$7;
    
    // Sub module instances
    top$pipeline$control$segment segment(
        .d(segment$d),
        .q(segment$q),
        .clock(segment$clock)
    );
    top$pipeline$control$ray ray(
        .d(ray$d),
        .q(ray$q),
        .clock(ray$clock)
    );
    top$pipeline$control$scanline scanline(
        .d(scanline$d),
        .q(scanline$q),
        .clock(scanline$clock)
    );
    top$pipeline$control$late late(
        .clock(late$clock),
        .data_in(late$data_in),
        .write_enable(late$write_enable),
        .data_out(late$data_out)
    );
    top$pipeline$control$weights$0 weights$0(
        .address(weights$0$address),
        .data(weights$0$data)
    );
    top$pipeline$control$weights$1 weights$1(
        .address(weights$1$address),
        .data(weights$1$data)
    );
    top$pipeline$control$weights$2 weights$2(
        .address(weights$2$address),
        .data(weights$2$data)
    );
    top$pipeline$control$weights$3 weights$3(
        .address(weights$3$address),
        .data(weights$3$data)
    );
    top$pipeline$control$bounds$0 bounds$0(
        .address(bounds$0$address),
        .data(bounds$0$data)
    );
    top$pipeline$control$bounds$1 bounds$1(
        .address(bounds$1$address),
        .data(bounds$1$data)
    );
    top$pipeline$control$bounds$2 bounds$2(
        .address(bounds$2$address),
        .data(bounds$2$data)
    );
    top$pipeline$control$bounds$3 bounds$3(
        .address(bounds$3$address),
        .data(bounds$3$data)
    );
    top$pipeline$control$inner$0 inner$0(
        .address(inner$0$address),
        .data(inner$0$data)
    );
    top$pipeline$control$inner$1 inner$1(
        .address(inner$1$address),
        .data(inner$1$data)
    );
    top$pipeline$control$inner$2 inner$2(
        .address(inner$2$address),
        .data(inner$2$data)
    );
    top$pipeline$control$inner$3 inner$3(
        .address(inner$3$address),
        .data(inner$3$data)
    );
    
    // Update code
    always @(*) begin
        segment$clock = clock;
        ray$clock = clock;
        scanline$clock = clock;
        segment$d = segment$q;
        ray$d = ray$q;
        scanline$d = scanline$q;
        late$clock = clock;
        late$write_enable = 1'b1;
        if (valid) begin
            segment$d = segment$q + 'h1;
            if (segment$q == last_segment) begin
                segment$d = 'h0;
                ray$d = ray$q + 'h1;
                if (ray$q == last_ray) begin
                    ray$d = 'h0;
                    scanline$d = scanline$q + 'h1;
                end
            end
        end
        if (start) begin
            segment$d = 'h0;
            ray$d = 'h0;
            scanline$d = 'h0;
        end
        first = valid & ~|segment$q;
        late$data_in = 64'(segment$q) | (64'(ray$q) << 'h10) | (64'(scanline$q) << 'h20);
        if (valid) begin
            late$data_in = 64'(segment$q) | (64'(ray$q) << 'h10) | (64'(scanline$q) << 'h20) | valid_flag;
        end
        unit_segment = late$data_out[('h0)+:(16)];
        unit_ray = late$data_out[('h10)+:(16)];
        unit_scanline = late$data_out[('h20)+:(16)];
        unit_valid = late$data_out['h30];
        unit_first = late$data_out['h30] & ~|unit_segment;
        unit_last = late$data_out['h30] & (unit_segment == last_segment);
        lane_in$0 = 'h0;
        lane_inner$0 = 'h0;
        lane_in$1 = 'h0;
        lane_inner$1 = 'h0;
        lane_in$2 = 'h0;
        lane_inner$2 = 'h0;
        lane_in$3 = 'h0;
        lane_inner$3 = 'h0;
        lane_in$4 = 'h0;
        lane_inner$4 = 'h0;
        lane_in$5 = 'h0;
        lane_inner$5 = 'h0;
        lane_in$6 = 'h0;
        lane_inner$6 = 'h0;
        lane_in$7 = 'h0;
        lane_inner$7 = 'h0;
        weights$0$address = unit_segment[('h0)+:(8)];
        bounds$0$address = unit_segment[('h0)+:(8)];
        wx$0 = weights$0$data[('h0)+:(16)];
        wy$0 = weights$0$data[('h10)+:(16)];
        if ((unit_ray >= bounds$0$data[('h0)+:(16)]) & (unit_ray <= bounds$0$data[('h10)+:(16)]) & (unit_scanline >= bounds$0$data[('h20)+:(16)]) & (unit_scanline <= bounds$0$data[('h30)+:(16)])) begin
            lane_in$0 = lane_bit$0;
        end
        inner$0$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$0$data[('h0)+:(16)]) & (unit_ray <= inner$0$data[('h10)+:(16)]) & (unit_scanline >= inner$0$data[('h20)+:(16)]) & (unit_scanline <= inner$0$data[('h30)+:(16)])) begin
            lane_inner$0 = lane_bit$0;
        end
        weights$1$address = unit_segment[('h0)+:(8)];
        bounds$1$address = unit_segment[('h0)+:(8)];
        wx$1 = weights$1$data[('h0)+:(16)];
        wy$1 = weights$1$data[('h10)+:(16)];
        if ((unit_ray >= bounds$1$data[('h0)+:(16)]) & (unit_ray <= bounds$1$data[('h10)+:(16)]) & (unit_scanline >= bounds$1$data[('h20)+:(16)]) & (unit_scanline <= bounds$1$data[('h30)+:(16)])) begin
            lane_in$1 = lane_bit$1;
        end
        inner$1$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$1$data[('h0)+:(16)]) & (unit_ray <= inner$1$data[('h10)+:(16)]) & (unit_scanline >= inner$1$data[('h20)+:(16)]) & (unit_scanline <= inner$1$data[('h30)+:(16)])) begin
            lane_inner$1 = lane_bit$1;
        end
        weights$2$address = unit_segment[('h0)+:(8)];
        bounds$2$address = unit_segment[('h0)+:(8)];
        wx$2 = weights$2$data[('h0)+:(16)];
        wy$2 = weights$2$data[('h10)+:(16)];
        if ((unit_ray >= bounds$2$data[('h0)+:(16)]) & (unit_ray <= bounds$2$data[('h10)+:(16)]) & (unit_scanline >= bounds$2$data[('h20)+:(16)]) & (unit_scanline <= bounds$2$data[('h30)+:(16)])) begin
            lane_in$2 = lane_bit$2;
        end
        inner$2$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$2$data[('h0)+:(16)]) & (unit_ray <= inner$2$data[('h10)+:(16)]) & (unit_scanline >= inner$2$data[('h20)+:(16)]) & (unit_scanline <= inner$2$data[('h30)+:(16)])) begin
            lane_inner$2 = lane_bit$2;
        end
        weights$3$address = unit_segment[('h0)+:(8)];
        bounds$3$address = unit_segment[('h0)+:(8)];
        wx$3 = weights$3$data[('h0)+:(16)];
        wy$3 = weights$3$data[('h10)+:(16)];
        if ((unit_ray >= bounds$3$data[('h0)+:(16)]) & (unit_ray <= bounds$3$data[('h10)+:(16)]) & (unit_scanline >= bounds$3$data[('h20)+:(16)]) & (unit_scanline <= bounds$3$data[('h30)+:(16)])) begin
            lane_in$3 = lane_bit$3;
        end
        inner$3$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$3$data[('h0)+:(16)]) & (unit_ray <= inner$3$data[('h10)+:(16)]) & (unit_scanline >= inner$3$data[('h20)+:(16)]) & (unit_scanline <= inner$3$data[('h30)+:(16)])) begin
            lane_inner$3 = lane_bit$3;
        end
        in_volume = lane_in$0 | lane_in$1 | lane_in$2 | lane_in$3 | lane_in$4 | lane_in$5 | lane_in$6 | lane_in$7;
        in_inner = lane_inner$0 | lane_inner$1 | lane_inner$2 | lane_inner$3 | lane_inner$4 | lane_inner$5 | lane_inner$6 | lane_inner$7;
    end
    
endmodule // top$pipeline$control
module top$pipeline$control$bounds$0(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h20000100380019;
      8'h1: data = 64'h21000300340016;
      8'h2: data = 64'h23000500310013;
      8'h3: data = 64'h250007002e0010;
      8'h4: data = 64'h270009002b000d;
      8'h5: data = 64'h29000b0028000a;
      8'h6: data = 64'h2b000d00250007;
      8'h7: data = 64'h2d000f00220004;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$bounds$0
module top$pipeline$control$bounds$1(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h20000200370019;
      8'h1: data = 64'h22000400340016;
      8'h2: data = 64'h24000600310013;
      8'h3: data = 64'h260008002d000f;
      8'h4: data = 64'h270009002a000c;
      8'h5: data = 64'h29000b00270009;
      8'h6: data = 64'h2b000d00240006;
      8'h7: data = 64'h2d000f00210003;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$bounds$1
module top$pipeline$control$bounds$2(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h20000200360018;
      8'h1: data = 64'h22000400330015;
      8'h2: data = 64'h24000600300012;
      8'h3: data = 64'h260008002d000f;
      8'h4: data = 64'h28000a002a000c;
      8'h5: data = 64'h2a000c00260008;
      8'h6: data = 64'h2c000e00230005;
      8'h7: data = 64'h2d000f00200002;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$bounds$2
module top$pipeline$control$bounds$3(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h21000300350017;
      8'h1: data = 64'h23000500320014;
      8'h2: data = 64'h250007002f0011;
      8'h3: data = 64'h260008002c000e;
      8'h4: data = 64'h28000a0029000b;
      8'h5: data = 64'h2a000c00260008;
      8'h6: data = 64'h2c000e00230005;
      8'h7: data = 64'h2e001000000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$bounds$3
module top$pipeline$control$inner$0(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h100000001;
      8'h1: data = 64'h100000001;
      8'h2: data = 64'h100000001;
      8'h3: data = 64'h100000001;
      8'h4: data = 64'h100000001;
      8'h5: data = 64'h100000001;
      8'h6: data = 64'h100000001;
      8'h7: data = 64'h100000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$inner$0
module top$pipeline$control$inner$1(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h100000001;
      8'h1: data = 64'h100000001;
      8'h2: data = 64'h100000001;
      8'h3: data = 64'h100000001;
      8'h4: data = 64'h100000001;
      8'h5: data = 64'h100000001;
      8'h6: data = 64'h100000001;
      8'h7: data = 64'h100000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$inner$1
module top$pipeline$control$inner$2(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h100000001;
      8'h1: data = 64'h100000001;
      8'h2: data = 64'h100000001;
      8'h3: data = 64'h100000001;
      8'h4: data = 64'h100000001;
      8'h5: data = 64'h100000001;
      8'h6: data = 64'h100000001;
      8'h7: data = 64'h100000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$inner$2
module top$pipeline$control$inner$3(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h100000001;
      8'h1: data = 64'h100000001;
      8'h2: data = 64'h100000001;
      8'h3: data = 64'h100000001;
      8'h4: data = 64'h100000001;
      8'h5: data = 64'h100000001;
      8'h6: data = 64'h100000001;
      8'h7: data = 64'h100000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$inner$3
module top$pipeline$control$late(clock,data_in,write_enable,data_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] data_in;
    input wire  write_enable;
    output reg  [63:0] data_out;
    
    // Constant declarations
    localparam  last = 16'h8;
    localparam  single = 1'b0;
    localparam  mask = 64'hffffffffffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [63:0] one$d;
    wire  [63:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$control$late$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$control$late$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$control$late$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    always @(*) begin
        ptr$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        next = ptr$q + 'h1;
        if (ptr$q == last) begin
            next = 'h0;
        end
        ptr$d = next;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = next;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single) begin
            data_out = one$q;
        end
        else begin
            data_out = ram$read_data;
        end
    end
    
endmodule // top$pipeline$control$late
module top$pipeline$control$late$one(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$control$late$one
module top$pipeline$control$late$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$control$late$ptr
module top$pipeline$control$late$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [63:0] mem[8:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[3:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[3:0]] <= write_data;
       end
    end
endmodule // top$pipeline$control$late$ram
module top$pipeline$control$ray(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$control$ray
module top$pipeline$control$scanline(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$control$scanline
module top$pipeline$control$segment(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$control$segment
module top$pipeline$control$weights$0(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [31:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 'h100000;
      8'h1: data = 'h340018;
      8'h2: data = 'h580030;
      8'h3: data = 'h7c0038;
      8'h4: data = 'h900050;
      8'h5: data = 'hb40068;
      8'h6: data = 'hd80080;
      8'h7: data = 'hfc0098;
      default: data = 'h0;
    endcase
            
endmodule // top$pipeline$control$weights$0
module top$pipeline$control$weights$1(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [31:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 'h8900b6;
      8'h1: data = 'had00ce;
      8'h2: data = 'hd100e6;
      8'h3: data = 'hf5000e;
      8'h4: data = 'h290026;
      8'h5: data = 'h4d002e;
      8'h6: data = 'h710046;
      8'h7: data = 'h85005e;
      default: data = 'h0;
    endcase
            
endmodule // top$pipeline$control$weights$1
module top$pipeline$control$weights$2(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [31:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 'h22007c;
      8'h1: data = 'h460094;
      8'h2: data = 'h6a00ac;
      8'h3: data = 'h7e00c4;
      8'h4: data = 'ha200dc;
      8'h5: data = 'hc60004;
      8'h6: data = 'hea001c;
      8'h7: data = 'h1e0034;
      default: data = 'h0;
    endcase
            
endmodule // top$pipeline$control$weights$2
module top$pipeline$control$weights$3(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [31:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 'h9b0042;
      8'h1: data = 'hbf005a;
      8'h2: data = 'he30072;
      8'h3: data = 'h17008a;
      8'h4: data = 'h3b00a2;
      8'h5: data = 'h5f00ba;
      8'h6: data = 'h8300d2;
      8'h7: data = 'h9700ea;
      default: data = 'h0;
    endcase
            
endmodule // top$pipeline$control$weights$3
